"""The study end to end: reproducibility, chunking, conservation, the clearance property."""

import json

import numpy as np
import pytest
import xarray as xr
from hypothesis import given
from hypothesis import strategies as st

import stackup.schemes as schemes
from stackup.assembly import ASSEMBLED, BLOCK_SCRAPPED, CRANK_SCRAPPED, SHELL_STOCKOUT, STATUS
from stackup.cli import main
from stackup.engines import engine_path, load_engine
from stackup.io import open_dataset, save
from stackup.study import ISO_SCHEMES, Study


def small(engine, **kw):
    return Study(**{"engine": str(engine), "n_engines": 120, "seed": 5, "pilot_engines": 2000, "progress": False, **kw})


def test_same_seed_gives_identical_dataset(engine_file):
    engine = engine_file()
    xr.testing.assert_identical(small(engine).run(), small(engine).run())


def test_different_seed_gives_different_parts(engine_file):
    engine = engine_file()
    a, b = small(engine).run(), small(engine, seed=6).run()
    assert not np.array_equal(a.housing_bore.values, b.housing_bore.values)


@given(chunk=st.integers(1, 4))
def test_chunking_does_not_change_the_numbers(engine_file, chunk):
    engine = engine_file(lot=30)
    reference = small(engine, chunk_lots=5).run()
    chunked = small(engine, chunk_lots=chunk).run()
    xr.testing.assert_equal(reference, chunked)


@given(seed=st.integers(0, 2**32), scheme=st.sampled_from(ISO_SCHEMES))
def test_zero_gauge_error_keeps_every_bearing_within_clearance_limits(engine_file, seed, scheme):
    ds = small(engine_file(gauge=0.0), seed=seed, schemes=(scheme,)).run()
    c = ds.clearance_nominal.values[ds.status.values == ASSEMBLED]
    lo, hi = schemes.load(scheme).clearance_limits()
    assert c.size > 0
    assert c.min() >= lo - 1e-12 and c.max() <= hi + 1e-12


@pytest.mark.integration
@given(seed=st.integers(0, 2**32), surplus=st.sampled_from([0.0, 0.02, 0.1]), supply=st.sampled_from(["to-order", "sorted"]))
def test_parts_are_conserved(engine_file, seed, surplus, supply):
    ds = small(engine_file(surplus=surplus, supply=supply, cpk=0.8), seed=seed).run()
    made = ds.shells_made.sum("shell_grade") + ds.shells_scrapped
    used = ds.shells_used.sum("shell_grade")
    left = ds.shells_left.sum("shell_grade")
    expected = int(np.ceil(2 * 50 * 5 * (1 + surplus))) * 2 + int(np.ceil(2 * 20 * 5 * (1 + surplus)))  # lots 50, 50, 20
    assert np.all(made == expected)
    np.testing.assert_array_equal(made, used + ds.shells_scrapped + left)
    # every fitted shell belongs to an assembled bearing, two each
    assert np.all(used == 2 * (ds.status == ASSEMBLED).sum(("engine", "bearing")))
    # every bearing is accounted for, by exactly one status
    counts = [(ds.status == k).sum(("engine", "bearing")) for k in range(len(STATUS))]
    assert np.all(sum(counts) == ds.sizes["engine"] * ds.sizes["bearing"])


def test_scrapped_block_marks_all_its_bearings(engine_file):
    ds = small(engine_file(cpk=0.5), n_engines=300).run()
    scrapped = ds.block_scrapped.values
    assert scrapped.any()
    assert np.all(ds.status.values[:, scrapped, :] == BLOCK_SCRAPPED)
    crank_only = ds.crank_scrapped.values & ~scrapped
    assert np.all(ds.status.values[:, crank_only, :] == CRANK_SCRAPPED)
    assert np.all(np.isnan(ds.clearance_nominal.values[ds.status.values != ASSEMBLED]))


def test_stockout_is_marked_not_dropped(engine_file):
    # No surplus and shells sorted from one process: some bins run dry.
    ds = small(engine_file(surplus=0.0, supply="sorted"), n_engines=200, schemes=("iso13778-4",)).run()
    stockout = ds.status.values == SHELL_STOCKOUT
    assert stockout.any()
    assert np.all(ds.shell_upper_grade.values[stockout] == "")


def test_gauge_error_widens_the_clearance_spread(engine_file):
    kw = {"n_engines": 3000, "schemes": ("iso13778-6",)}
    exact = small(engine_file(gauge=0.0), **kw).run()
    noisy = small(engine_file(gauge=0.002), **kw).run()
    assert float(noisy.clearance_nominal.std()) > 1.2 * float(exact.clearance_nominal.std())


def test_every_variable_has_units_and_long_name_and_attrs_reproduce_the_study(engine_file):
    ds = small(engine_file()).run()
    for name, var in ds.data_vars.items():
        assert "units" in var.attrs and "long_name" in var.attrs, name
    params = json.loads(ds.attrs["study"])
    assert params["seed"] == 5 and params["n_engines"] == 120
    xr.testing.assert_identical(Study(**params, progress=False).run(), ds)


@pytest.mark.parametrize("suffix", [".nc", ".zarr"])
@pytest.mark.parametrize("keep", ["everything", "summaries"])
def test_saved_datasets_round_trip_identically(engine_file, tmp_path, suffix, keep):
    ds = small(engine_file(), keep=keep).run()
    xr.testing.assert_identical(open_dataset(save(ds, tmp_path / f"x{suffix}")), ds)


@pytest.mark.parametrize(
    "kw, message",
    [
        ({"n_engines": 0}, "n_engines: 0 is not valid; must be >= 1"),
        ({"n_engines": 2.5}, "n_engines: 2.5 is not an integer"),
        ({"seed": -1}, "seed: -1 is not valid"),
        ({"schemes": ()}, "schemes: give at least one scheme"),
        ({"schemes": ("iso13778-4", "iso13778-4")}, "names a scheme twice"),
        ({"window": (45, 65)}, r"window: \(45.0, 65.0\) m is not a clearance window; .* in metres"),
        ({"window": (65e-6, 45e-6)}, "is not a clearance window"),
        ({"window": 50e-6}, "is not a \\(lower, upper\\) pair"),
    ],
)
def test_bad_study_input(kw, message):
    with pytest.raises(ValueError, match=message):
        Study(**kw)


def test_unknown_scheme_and_engine():
    with pytest.raises(ValueError, match="scheme: 'nope' is not a known scheme"):
        Study(schemes=("nope",), n_engines=10).run()
    with pytest.raises(ValueError, match="engine: 'nope' is not a built-in engine"):
        Study(engine="nope", n_engines=10).run()


@pytest.mark.parametrize(
    "old, new, message",
    [
        ('process = { distribution = "normal", cpk = 1.33 }\nshared = 0.3',
         'process = { distribution = "normal", cpk = -1 }\nshared = 0.3', r"housing_bore.process.cpk: -1 is not valid; must be > 0"),
        ("gauge = { repeatability = 0.0005 }\n\n[journal_d]", "gauge = { repeatability = -0.0005 }\n\n[journal_d]",
         r"housing_bore.gauge: gauge repeatability: -5e-07 is not valid; must be >= 0"),
        ("limits = [46.000, 46.018]", "limits = [46.018, 46.000]", r"journal_d.limits: upper limit 46 mm is below lower limit 46.018 mm"),
        ("shared = 0.2", "shared = nan", r"journal_d.shared: nan is not a finite number"),
        ('supply = "to-order"', 'supply = "to-stock"', r"shell_wall.supply: 'to-stock' is not one of 'to-order', 'sorted'"),
    ],
)
def test_bad_engine_file(engine_file, write_toml, old, new, message):
    text = engine_file().read_text()
    assert old in text
    bad = write_toml("bad-engine.toml", text.replace(old, new, 1))
    with pytest.raises(ValueError, match=message):
        Study(engine=str(bad), n_engines=10).run()


@pytest.mark.integration
def test_cli_compare_writes_dataset_and_report(tmp_path, capsys):
    assert main(["compare", "--n", "300", "--schemes", "iso13778-4", "iso13778-6", "--no-design", "--out", str(tmp_path)]) == 0
    for name in ("compare.nc", "report.md", "report.html", "clearance_histogram.png", "grade_usage.png", "sensitivity.png"):
        assert (tmp_path / name).is_file()
    page = (tmp_path / "report.html").read_text()
    assert page.count("<table>") >= 5 and "## " not in page
    import re
    sources = re.findall(r'src="([^"]+)"', page)
    assert sources and all(src.startswith("data:image/png;base64,") for src in sources)  # self-contained
    text = (tmp_path / "report.md").read_text()
    assert "iso13778-6" in text and "outside stated [ppm]" in text
    ds = open_dataset(tmp_path / "compare.nc")
    assert list(ds.scheme.values) == ["iso13778-4", "iso13778-6"]


def test_cli_reports_bad_input_as_an_error(capsys):
    assert main(["compare", "--n", "100", "--schemes", "iso13778-9"]) == 2
    assert "is not a known scheme" in capsys.readouterr().err


def test_operating_clearance_is_the_press_fit_of_the_stored_parts(engine_file):
    from stackup.engines import load_engine
    from stackup.fit import press_fit

    engine = engine_file()
    ds = small(engine, schemes=("iso13778-5",)).run().sel(scheme="iso13778-5")
    ok = ds.status.values == ASSEMBLED
    bore = np.broadcast_to(ds.housing_bore.values, ok.shape)[ok]
    fit = press_fit(housing_bore=bore, shell_wall=0.5 * (ds.shell_upper_wall.values[ok] + ds.shell_lower_wall.values[ok]),
                    crush_height=0.5 * (ds.shell_upper_crush.values[ok] + ds.shell_lower_crush.values[ok]),
                    journal_d=ds.journal_d.values[ok], **load_engine(engine).press_fit.kwargs())
    np.testing.assert_array_equal(ds.clearance_operating.values[ok], fit.clearance)
    np.testing.assert_array_equal(ds.contact_pressure.values[ok], fit.contact_pressure)
    assert np.all(np.isnan(ds.clearance_operating.values[~ok]))
    lo, hi = ds.crush_height_limits.values
    crush = ds.shell_upper_crush.values[ok]
    assert crush.min() >= lo and crush.max() <= hi


def test_report_has_press_fit_section_with_intervals(engine_file, tmp_path):
    from stackup.report import SECTIONS, fit_summary, write_report
    from stackup.report import templates as words

    ds = small(engine_file()).run()
    summary = fit_summary(ds.assign(design_contact_pressure_min=40e6))  # a limit most bearings miss
    assert np.all(summary.low_pressure_ppm > 5e5)
    for lo, hi in summary.low_pressure_ci_ppm:
        assert lo < hi
    text = write_report(ds, tmp_path).read_text()
    lines = text.splitlines()
    assert all(words.SECTION.format(title=title) in lines for title in SECTIONS if title != "Designed scheme")
    assert "σ > 450 MPa [ppm]" in text or words.FIT_HIGH_STRESS.format(stress=450) in text


def test_crank_stage_runs_on_the_subsample_and_marks_the_rest():
    from stackup.crank.cycle import CYCLE_STATUS, NOT_COMPUTED

    ds = Study(n_engines=40, mechanics_engines=6, crank_angle_step=4.0, schemes=("iso13778-4",), seed=2,
               pilot_engines=2000, progress=False).run()
    status = ds.crank_status.values[0]
    assert ds.crank_status.dims == ("scheme", "mech_engine")
    assert list(ds.mech_engine.values) == list(range(6))  # the rest are not computed: not on mech_engine
    assert not np.any(status == NOT_COMPUTED)
    assert np.all(status[:6] == 0)
    assert ds.crank_status.attrs["flag_meanings"] == " ".join(CYCLE_STATUS)
    r = ds.reaction_max.values[0]
    assert np.all(np.isfinite(r[:6])) and r.shape[0] == 6
    assert np.all((r[:6] > 5e3) & (r[:6] < 1e5))  # a 13 MPa, 76 mm bore four: kN to tens of kN


def test_crank_angle_step_must_divide_the_cycle():
    with pytest.raises(ValueError, match="crank_angle_step: 7.0 deg does not divide 720 deg"):
        Study(crank_angle_step=7.0)


def test_qmc_sampler_is_reproducible_unbiased_and_conserves_parts(engine_file):
    engine = engine_file(lot=64)
    kw = dict(n_engines=256, schemes=("iso13778-4",))
    q1, q2 = small(engine, sampler="qmc", **kw).run(), small(engine, sampler="qmc", **kw).run()
    xr.testing.assert_identical(q1, q2)
    mc = small(engine, **kw).run()
    assert not np.array_equal(q1.housing_bore.values, mc.housing_bore.values)
    # same distribution: the bore means agree within a few standard errors
    se = float(mc.housing_bore.std()) / np.sqrt(mc.housing_bore.size / 5)
    assert abs(float(q1.housing_bore.mean() - mc.housing_bore.mean())) < 4 * se
    made = q1.shells_made.sum("shell_grade") + q1.shells_scrapped
    np.testing.assert_array_equal(made, q1.shells_used.sum("shell_grade") + q1.shells_scrapped + q1.shells_left.sum("shell_grade"))
    with pytest.raises(ValueError, match="sampler: 'sobol' is not one of 'mc', 'qmc'"):
        Study(sampler="sobol")


def test_fidelity_tier_per_stage():
    kw = dict(n_engines=60, mechanics_engines=3, schemes=("iso13778-4",), crank_angle_step=8.0, pilot_engines=2000,
              progress=False)
    law = Study(**kw).run()
    rigid = Study(**kw, crank_method="rigid", fit_method="thin-ring").run()
    assert not np.allclose(law.reaction_max.values[0, :3], rigid.reaction_max.values[0, :3])
    assert not np.allclose(law.clearance_operating.values, rigid.clearance_operating.values, equal_nan=True)
    with pytest.raises(ValueError, match="crank_method: 'beam' is not one of"):
        Study(crank_method="beam")
    with pytest.raises(ValueError, match="fit_method: 'exact' is not one of"):
        Study(fit_method="exact")


@pytest.mark.integration
def test_target_error_sizes_the_mechanical_chain_independently_of_chunking():
    kw = dict(n_engines=2000, schemes=("iso13778-4",), crank_angle_step=8.0, mechanics_engines=300, pilot_engines=2000,
              progress=False)
    loose = Study(**kw, target_error=0.02).run()
    tight = Study(**kw, target_error=0.001).run()
    assert loose.attrs["mechanics_engines_used"] < tight.attrs["mechanics_engines_used"] <= 300
    assert loose.attrs["mechanics_engines_used"] % 25 == 0
    rechunked = Study(**kw, target_error=0.02, chunk_lots=1).run()
    xr.testing.assert_equal(loose, rechunked)
    used = loose.attrs["mechanics_engines_used"]
    assert loose.sizes["mech_engine"] == used  # nothing beyond the sample


def test_history_on_a_crank_angle_dimension_only_when_asked():
    kw = dict(n_engines=100, schemes=("iso13778-5",), crank_angle_step=6.0, mechanics_engines=4, pilot_engines=2000,
              progress=False)
    plain = Study(**kw).run()
    assert "crank_angle" not in plain.dims
    ds = Study(**kw, history=True).run()
    assert ds.h_min_history.dims == ("scheme", "mech_engine", "bearing", "crank_angle")
    assert ds.sizes["crank_angle"] == 120 and ds.sizes["mech_engine"] == 4
    np.testing.assert_allclose(ds.h_min_history.min("crank_angle").values, ds.h_min.values[:, :4])
    np.testing.assert_allclose(np.linalg.norm(ds.load_history.values, axis=-1).max(axis=-1), ds.reaction_max.values[:, :4])
    assert ds.crank_angle.attrs["units"] == "degree"


def test_a_study_window_overrides_the_engines_for_counts_and_ranking(engine_file):
    from stackup import rank

    kw = dict(keep="summaries", schemes=("iso13778-4",))
    narrow, wide = (small(engine_file(), window=w, **kw).run() for w in ((30e-6, 31e-6), (10e-6, 200e-6)))
    assert tuple(wide.clearance_window.values) == (10e-6, 200e-6)
    assert int(wide.outside_window_count.sum()) == 0 < int(narrow.outside_window_count.sum())
    assert rank(wide).loc["iso13778-4", "outside_window_ppm"] == 0 < rank(narrow).loc["iso13778-4", "outside_window_ppm"]


def test_a_stage_failing_on_many_engines_stops_the_run_naming_stage_share_and_cause(engine_file, write_toml):
    from stackup.study.failures import FailureCount, StageFailure

    # a scheme whose journal grades start 6 um above the drawing's lower limit: about 8 % cannot be graded
    text = (schemes.builtin_folder() / "iso13778-4.toml").read_text().replace(
        "A = [46.000, 46.006], B = [46.006, 46.012], C = [46.012, 46.018]",
        "A = [46.006, 46.012], B = [46.012, 46.018], C = [46.018, 46.024]")
    wrong = write_toml("shifted.toml", text.replace('name = "iso13778-4"', 'name = "shifted"'))
    with pytest.raises(StageFailure, match=r"grading: failed on .* of .* bearings with parts inside their drawing "
                                           r"limits \(\d+\.\d %, more than the study's failure_limit of 5 %\); "
                                           r"likely cause: the scheme's grade ranges"):
        small(engine_file(), schemes=(str(wrong),), n_engines=120, pilot_engines=2000).run()
    counts = FailureCount.of_dataset(small(engine_file(), schemes=(str(wrong),), failure_limit=1.0).run())
    assert 0.05 < counts.shares()["grading"] < 0.2 and "grading: failed on" in counts.lines()[0]


def test_press_fit_checks_use_the_engines_limits_at_every_declared_temperature():
    engine = load_engine("iso-example-aluminium")
    ds = Study(engine="iso-example-aluminium", n_engines=300, mechanics_engines=0, progress=False,
               pilot_engines=2000, schemes=("iso13778-4",)).run()
    limits = engine.press_fit_limits
    assert float(ds.design_contact_pressure_min) == limits.contact_pressure_min
    assert float(ds.design_shell_stress_max) == limits.shell_stress_max
    assert ds.attrs["press_fit_limits_source"] == limits.source != ""
    np.testing.assert_array_equal(ds.press_fit_temperatures.values, engine.press_fit.temperatures)
    ok = ds.status.values == 0
    # an aluminium housing shrinks onto the steel backs when cold: the stress check bites there, well above
    # the stress at the operating temperature (Kopeliovich, sec. 6: about 100 MPa more at 80 K colder)
    extra = (ds.shell_stress_highest.values - ds.shell_stress.values)[ok]
    assert extra.min() > 80e6


def test_a_dataset_reruns_identically_with_no_input_file_present(tmp_path):
    engine = tmp_path / "my-engine.toml"
    engine.write_text(engine_path("iso-example").read_text())
    scheme_file = tmp_path / "mine.toml"
    schemes.load("iso13778-5").to_toml(scheme_file)
    designed = schemes.load("iso13778-4")  # a Scheme object, as the designer gives
    kw = dict(n_engines=400, mechanics_engines=2, crank_angle_step=12.0, progress=False, pilot_engines=1000)
    ds = Study(engine=str(engine), schemes=(str(scheme_file), designed), **kw).run()
    stored = json.loads(ds.attrs["input_files"])
    assert stored["engine"]["text"] == engine.read_text() and set(stored["schemes"]) == {str(scheme_file), "iso13778-4"}
    engine.unlink()
    scheme_file.unlink()
    xr.testing.assert_identical(Study.from_dataset(ds).run(), ds)
    # an edited engine text is another study: the rerun follows the stored text, not a file of the same name
    edited = json.loads(ds.attrs["input_files"])
    edited["engine"]["text"] = edited["engine"]["text"].replace("shared = 0.3", "shared = 0.0", 1)
    assert edited != stored
    other = Study.from_dataset(ds, files=edited).run()
    assert not other.housing_bore.equals(ds.housing_bore)


@pytest.mark.parametrize("name, scheme", [("iso-example", "iso13778-4"), ("iso-example-aluminium", "iso13778-2")])
def test_chain_root_model_and_designer_give_identical_operating_clearance(name, scheme):
    """One operating-clearance core: the study's chain, the root model of tails and Sobol and the designer's
    call at a wall sum give the same numbers, bit for bit, on the same parts and shells."""
    from types import SimpleNamespace

    from stackup.design.sample import clearance_at
    from stackup.study import chain
    from stackup.study.pilot import pilot_parts, shell_plan
    from stackup.study.roots import RootModel

    engine, scheme = load_engine(name), schemes.load(scheme)
    shells = ("shell_upper_wall", "shell_lower_wall", "shell_upper_crush", "shell_lower_crush")

    def designer(values):
        crush = np.stack([values["shell_upper_crush"], values["shell_lower_crush"]], axis=-1)
        return clearance_at(engine, housing_bore=values["housing_bore"], journal_d=values["journal_d"], crush=crush,
                            wall_sum=values["shell_upper_wall"] + values["shell_lower_wall"])

    # the root model's engines through the chain's press fit and the designer's call
    model = RootModel(engine, scheme, shell_plan(engine, scheme, pilot_parts(engine, 0, 2000)).aim)
    roots = model.engines(np.random.default_rng(3).random((64, len(model.columns()[0]))))
    graded = np.isfinite(roots["clearance_operating"])
    assert graded.mean() > 0.9
    values = {k: roots[k][graded] for k in ("housing_bore", "journal_d", *shells)}
    parts = SimpleNamespace(housing_bore=values["housing_bore"], journal_d=values["journal_d"])
    assembly = SimpleNamespace(status=np.full(graded.sum(), ASSEMBLED),
                               **{k.removeprefix("shell_"): values[k] for k in shells})
    from_chain = chain._press_fit(engine, parts, assembly, "lame")["clearance_operating"]
    np.testing.assert_array_equal(from_chain, roots["clearance_operating"][graded])
    np.testing.assert_array_equal(designer(values), roots["clearance_operating"][graded])

    # a study's assembled bearings through the designer's call
    ds = Study(engine=name, schemes=(scheme.name,), n_engines=60, seed=2, pilot_engines=2000, mechanics_engines=0,
               progress=False).run().isel(scheme=0)
    built = ds.status.values == ASSEMBLED
    values = {k: np.broadcast_to(ds[k].values, built.shape)[built] for k in ("housing_bore", "journal_d", *shells)}
    np.testing.assert_array_equal(designer(values), ds.clearance_operating.values[built])


def test_the_chain_runs_its_stages_with_their_checks_skipped(monkeypatch):
    """The study checks its inputs where they enter; the stages it calls skip theirs (stackup._validate.trusted)."""
    from stackup import _validate
    from stackup.study import chain

    seen = {}

    def spy(name, function):
        def call(*args, **kwargs):
            seen.setdefault(name, set()).add(_validate._TRUSTED.get())
            return function(*args, **kwargs)
        monkeypatch.setattr(chain, name, call)

    for name in ("draw_lot", "assemble", "operating_clearance", "engine_cycles", "bearing_films", "levanov_method1"):
        spy(name, getattr(chain, name))
    Study(n_engines=40, schemes=("iso13778-4",), mechanics_engines=2, pilot_engines=2000, seed=1,
          film_method="mobility", progress=False).run()
    assert seen == dict.fromkeys(seen, {True}) and len(seen) == 6
    assert _validate._TRUSTED.get() is False


def test_the_old_name_of_the_reynolds_transient_film_tier_is_still_accepted():
    import warnings

    from stackup.film.cycle import FILM_METHODS

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", DeprecationWarning)
        study = Study(film_method="transient", n_engines=10)
    assert study.film_method in FILM_METHODS
