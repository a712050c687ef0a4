"""The report is a function of saved datasets alone: no sampling, no backend change, full or summary datasets."""

import json
import subprocess
import sys
import tomllib
from dataclasses import replace

import numpy as np
import pytest

import stackup
import stackup.schemes as schemes
from stackup.io import open_comparison, save_comparison
from stackup.report import clearance_summary, fit_summary, write_report

KW = dict(schemes=("iso13778-4", "iso13778-6"), n_engines=600, seed=4, pilot_engines=3000, mechanics_engines=12,
          crank_angle_step=12.0, progress=False)
SCENARIOS = {"bore mean +1σ": {"housing_shift": 1.0}, "misalignment ×2": {"misalignment_scale": 2.0}}
DESIGN = {"n_engines": 500, "generations": 0, "name": "designed"}


@pytest.fixture(scope="module")
def comparison():
    return stackup.compare(**KW, scenarios=SCENARIOS, design=DESIGN)  # and the declared model uncertainties


def _no_randomness(monkeypatch):
    """Make every way of drawing random numbers raise."""
    def refuse(*args, **kwargs):
        raise AssertionError("the report drew random numbers")

    for name in ("Generator", "default_rng", "PCG64", "SeedSequence", "RandomState", "seed", "rand", "randn",
                 "random", "choice", "normal", "integers"):
        if hasattr(np.random, name):
            monkeypatch.setattr(np.random, name, refuse)


def test_compare_runs_the_study_its_scenarios_and_the_sensitivity(comparison):
    from stackup.engines import load_engine
    from stackup.scenarios import model_uncertainties

    model = [label for u in model_uncertainties(load_engine("iso-example")) for label in u.scenarios]
    assert list(comparison.scenarios) == [*SCENARIOS, *model]
    assert [ds.attrs["scenario_kind"] for ds in comparison.scenarios.values()] == ["process"] * 2 + ["model"] * 8
    assert comparison.scenarios["housing OD 75 mm"].attrs["scenario_source"].startswith("assumed")
    assert all(ds.attrs["kept"] == "summaries" for ds in comparison.scenarios.values())
    assert comparison.scenarios["misalignment ×2"].attrs["mechanics_engines_used"] > 0
    assert comparison.scenarios["bore mean +1σ"].attrs["mechanics_engines_used"] == 0
    assert set(comparison.sensitivity.output.values) == {"clearance_operating", "h_min", "life"}


def test_report_draws_no_random_number_and_reads_the_saved_comparison(comparison, tmp_path, monkeypatch):
    path = save_comparison(comparison, tmp_path / "compare.nc", compact=False)  # exact: the same report
    expected = write_report(comparison.dataset, tmp_path / "memory", scenarios=comparison.scenarios,
                            sensitivity=comparison.sensitivity, tails=comparison.tails).read_text()
    saved = open_comparison(path)
    assert list(saved.scenarios) == list(comparison.scenarios)
    assert saved.scenarios["journal 20 K hotter"].attrs["scenario_kind"] == "model"
    _no_randomness(monkeypatch)
    text = write_report(saved.dataset, tmp_path / "saved", scenarios=saved.scenarios,
                        sensitivity=saved.sensitivity, tails=saved.tails).read_text()
    assert text == expected
    assert "## Planning: shells per grade" in text and "misalignment ×2" in text



def test_the_command_line_writes_the_report_of_a_saved_comparison_again(comparison, tmp_path, capsys):
    from stackup.cli import main

    path = save_comparison(comparison, tmp_path / "compare.nc")
    saved = open_comparison(path)
    expected = write_report(saved.dataset, tmp_path / "library", scenarios=saved.scenarios,
                            sensitivity=saved.sensitivity, tails=saved.tails, dataset_file="compare.nc").read_text()
    assert main(["report", str(path)]) == 0
    assert (tmp_path / "report.md").read_text() == expected  # next to the dataset, naming it
    assert {"report.html", "clearance_histogram.png"} <= {p.name for p in tmp_path.iterdir()}
    assert main(["report", str(tmp_path / "compare.md")]) == 2
    assert "dataset: " in capsys.readouterr().err
    (tmp_path / "notes.nc").write_text("not a dataset")
    assert main(["report", str(tmp_path / "notes.nc"), "--out", str(tmp_path / "elsewhere")]) == 2
    assert "is not a comparison `stackup compare` saved" in capsys.readouterr().err


def _verdict(ds, **ranking):
    """The verdict of a study dataset alone (no scenarios), as one text."""
    from stackup.facts import facts
    from stackup.rank import ranked
    from stackup.report.verdict import verdict

    known = facts(ds, **ranking)
    return " ".join(verdict(known, ranked(known.ranking), {}))


def test_the_verdict_says_when_no_scheme_meets_the_window(comparison):
    ds = comparison.dataset
    text = _verdict(ds, window=(1e-6, 2e-6))
    assert "**Check first:** No scheme meets the window 1–2 µm:" in text
    text = _verdict(ds)
    assert "No scheme meets" not in text


def test_the_verdict_says_how_much_of_the_cycle_journal_edges_touch_where_most_bearings_do(comparison):
    from stackup.study.schema import flag

    ds = comparison.dataset
    status = ds.film_status.values
    computed = (status != flag(ds.film_status, "not_computed")) & ds.film_valid.values
    touching = computed & (status == flag(ds.film_status, "edge_contact"))
    text = _verdict(ds)
    assert ("Journal edges reach the wall" in text) == (touching.sum() >= 0.5 * computed.sum())
    # every bearing touching: said on the first page, with what α and the lives make of it
    edged = ds.copy()
    edged["film_status"] = edged.film_status.where(~computed, flag(ds.film_status, "edge_contact"))
    text = _verdict(edged)
    assert "**Check first:**" in text and "Journal edges reach the wall in 100 % of the bearings" in text
    assert "α and the lives read the film there" in text
    # a study saved when α and the lives read the mid-plane film: they ignore the contact, and the page says so
    midplane = edged.copy()
    midplane["h_min"] = midplane.h_min_midplane
    assert "Journal edges touch their shells in 100 % of the bearings; the lives ignore" in _verdict(midplane)
    # none touching: nothing said
    clear = ds.copy()
    clear["film_status"] = clear.film_status.where(~computed, flag(ds.film_status, "periodic"))
    assert "Journal edges" not in _verdict(clear)


def test_limits_say_what_the_film_tiers_cycle_mean_error_does_to_method_1s_life(comparison):
    from stackup.facts import facts
    from stackup.life import levanov_method1
    from stackup.report.methods import limits_of_validity

    ds = comparison.dataset
    wear = json.loads(ds.attrs["wear"])
    error = json.loads(ds.attrs["film_method_errors"])["h_min_mean"]
    films = ds.h_min_mean.values[np.isfinite(ds.h_min_mean.values)]
    h = float(np.median(films))
    life = levanov_method1(np.array([h, h / (1 + error)]), h_lim_cr=wear["critical_film_m"],
                           wear_limit=wear["method1_wear_limit_m"], wear_rate=wear["wear_rate_m_per_s"]).life
    text = " ".join(limits_of_validity(facts(ds)))
    assert f"up to {100 * error:.0f} % thicker than the transient reference" in text
    assert f"makes a life {life[0] / life[1]:.1f} times as long" in text and f"{h * 1e6:.1f} µm" in text
    cap = wear["method1_wear_limit_m"] / wear["wear_rate_m_per_s"] / 3600
    assert wear["method1_wear_limit_m"] / wear["wear_rate_m_per_s"] == pytest.approx(1e8)  # the paper's results' scale
    assert f"caps a life at Δh_lim/γ = {cap:,.0f} h" in text
    # a study without the tier's measured errors says nothing of it
    bare = ds.copy()
    bare.attrs = {k: v for k, v in ds.attrs.items() if k != "film_method_errors"}
    assert "Method 1 reads" not in " ".join(limits_of_validity(facts(bare)))


def test_the_film_section_gives_the_heat_balance_of_the_bearings(comparison, tmp_path):
    from stackup.study.schema import flag

    ds = comparison.dataset
    text = write_report(ds, tmp_path).read_text()
    valid = (ds.film_status.values != flag(ds.film_status, "not_computed")) & ds.film_valid.values
    temperature = np.percentile(ds.film_temperature.values[valid], [5, 50, 95])
    assert (f"The heat balance puts the films at {temperature[0]:.0f}-{temperature[2]:.0f} °C (5-95 %; median "
            f"{temperature[1]:.0f} °C, oil supplied at") in text
    assert "W of friction per bearing" in text and "L/min of oil." in text


def test_report_reads_limits_and_life_target_from_the_dataset(comparison, tmp_path):
    ds = comparison.dataset.assign(design_contact_pressure_min=20e6, design_shell_stress_max=300e6,
                                   life_target=1e9 * 3600)
    text = write_report(ds, tmp_path).read_text()
    # a check no bearing fails is said in a sentence, not as a column of zeros
    assert "p < 20 MPa [ppm]" in text or "falls below 20 MPa of contact pressure" in text
    assert "σ > 300 MPa [ppm]" in text or "compresses its shells beyond 300 MPa" in text
    assert "life < 1000000000 h, worst position [% of its bearings]" in text


def test_report_of_streaming_summaries_agrees_and_says_what_needs_every_engine(tmp_path):
    from dataclasses import replace

    full = stackup.Study(**KW).run()
    summary = replace(stackup.Study(**KW), keep="summaries").run()
    text = write_report(summary, tmp_path).read_text()
    assert "run the study with `keep=\"everything\"`" in text  # planning
    assert "none was given" in text  # contributions
    a, b = clearance_summary(full), clearance_summary(summary)
    np.testing.assert_allclose(b.mean_um, a.mean_um, rtol=1e-9)
    np.testing.assert_array_equal(b.outside_stated_ppm, a.outside_stated_ppm)  # stated ranges lie on the bin grid
    np.testing.assert_allclose(b.median_um, a.median_um, atol=0.05 + 1e-9)  # within half a 0.1 um bin
    fa, fb = fit_summary(full), fit_summary(summary)
    np.testing.assert_array_equal(fb.low_pressure_ppm, fa.low_pressure_ppm)
    np.testing.assert_allclose(fb.contact_pressure_min_mpa, fa.contact_pressure_min_mpa)


def test_importing_the_report_leaves_the_matplotlib_backend_alone():
    code = ("import matplotlib; matplotlib.use('svg'); import stackup.report, stackup.cli; "
            "print(matplotlib.get_backend())")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "svg"


def test_a_compact_file_keeps_every_variable_within_half_its_resolution(comparison, tmp_path):
    from stackup.io import open_dataset, save
    from stackup.study.schema import STORED_RESOLUTION, STORED_RESOLUTION_OF

    ds = comparison.dataset
    exact, compact = save(ds, tmp_path / "exact.nc"), save(ds, tmp_path / "compact.nc", compact=True)
    assert compact.stat().st_size < 0.5 * exact.stat().st_size  # 0.25 at the main job's size; headers weigh here
    back = open_dataset(compact)
    assert list(back.data_vars) == list(ds.data_vars)
    for name, var in ds.data_vars.items():
        if var.dtype.kind != "f":
            np.testing.assert_array_equal(back[name].values, var.values)
            continue
        np.testing.assert_array_equal(np.isnan(back[name].values), np.isnan(var.values))  # NaN stays NaN
        resolution = (STORED_RESOLUTION_OF.get(name, STORED_RESOLUTION.get(var.attrs["units"])) if var.ndim >= 2
                      else None)
        if resolution and np.isfinite(var.values).any():  # (an all-NaN variable, e.g. law_fit_error of the paper's law)
            assert np.nanmax(np.abs(back[name].values - var.values)) <= 0.5 * resolution * (1 + 1e-6)
        else:  # float32, or exact below two dimensions
            np.testing.assert_allclose(back[name].values, var.values, rtol=2**-23)
        assert back[name].attrs["units"] == var.attrs["units"]


def test_the_designed_scheme_is_compared_beside_the_others_and_explained(comparison, tmp_path):
    ds = comparison.dataset
    assert list(ds.scheme.values) == [*KW["schemes"], "designed"] and ds.attrs["designed_scheme"] == "designed"
    assert "designed" in comparison.tails.scheme.values
    design = json.loads(ds.attrs["design"])
    assert design["start"] in KW["schemes"] or design["start"].startswith("iso13778-")
    # the scheme the study ran is the one the designer wrote, stored as text: it reads back as that scheme
    text = json.loads(ds.attrs["input_files"])["schemes"]["designed"]
    assert schemes.from_dict(tomllib.loads(text)).clearance_limits() == pytest.approx(
        [float(v) for v in ds.clearance_limit.sel(scheme="designed").values], abs=1e-9)
    report = write_report(ds, tmp_path, scenarios=comparison.scenarios, sensitivity=comparison.sensitivity,
                          tails=comparison.tails).read_text()
    section = report.split("## Designed scheme")[1].split("\n## ")[0]
    assert "by `stackup.design` (" in section and f"from `{design['start']}`" in section
    assert "| housing bore |" in section
    assert "Its reasons are the comments of its scheme text" in section


def test_a_scheme_without_a_stated_range_shows_a_dash_not_zero_ppm(tmp_path):
    from stackup.study import Study
    from stackup.study.inputs import scheme_text

    text = "\n".join(line for line in scheme_text("iso13778-4").splitlines() if not line.startswith("stated_clearance"))
    path = tmp_path / "unstated.toml"
    path.write_text(text.replace('name = "iso13778-4"', 'name = "unstated"'))
    ds = Study(schemes=(str(path), "iso13778-3"), n_engines=300, mechanics_engines=0, progress=False,
               pilot_engines=1000).run()
    summary = clearance_summary(ds)
    assert np.isnan(summary.outside_stated_ppm["unstated"]) and np.isfinite(summary.outside_stated_ppm["iso13778-3"])
    report = write_report(ds, tmp_path / "report").read_text()
    row = next(line for line in report.splitlines() if line.startswith("| unstated | none ("))
    assert row.rstrip(" |").endswith("—")


def test_a_study_without_the_mechanical_chain_says_so(tmp_path):
    from stackup.facts import Run
    from stackup.report.verdict import run_notes
    from stackup.study import Study

    ds = Study(schemes=("iso13778-4",), n_engines=200, mechanics_engines=0, progress=False, pilot_engines=1000).run()
    notes = run_notes(Run.of(ds))
    assert any("did not run (the study asked for none" in note for note in notes)
    assert "did not run" in write_report(ds, tmp_path).read_text().split("<!-- /verdict -->")[0]


def test_numbers_are_written_one_way():
    from stackup.report import format as fmt

    assert fmt.significant(26_512) == "26,500" and fmt.significant(float("inf")) == "∞" and fmt.significant(0) == "0"
    assert fmt.significant_triple((34_584.9, 33_900.2, 35_412.0)) == "34,600 [33,900, 35,400]"
    assert fmt.ppm(0.0497, (0.034, 0.065)) == "0.050 ppm [0.034, 0.065]" and fmt.ppm(2354.2) == "2,354 ppm"
    assert fmt.interval(float("nan"), (1, 2)) == "—" and fmt.interval(1.234, (1.0, 1.5), 2) == "1.23 [1.00, 1.50]"
    assert fmt.um_edge(34.5e-6) == "34.5" and fmt.um_edge(57e-6) == "57" and fmt.um(8.79e-6) == "8.8"
    assert fmt.hours(37_987.9) == "38,000" and fmt.spaced(10_000) == "10 000" and fmt.count(10_465) == "10,465"


def _table_rows(text, heading, first_column):
    """The rows of the first table under ``heading`` whose first cells are ``first_column``, by that cell."""
    body = text.split(f"## {heading}\n")[1].split("\n## ")[0]
    block = next(b for b in body.split("\n\n") if b.startswith("| "))
    rows = [line.strip("|").split(" | ") for line in block.splitlines() if line.startswith("| ")]
    head = [cell.strip() for cell in rows[0]]
    return {row[head.index(first_column)].strip(): dict(zip(head, (c.strip() for c in row))) for row in rows[1:]}


def test_the_report_states_the_numbers_of_the_facts(comparison, tmp_path):
    from stackup.facts import facts
    from stackup.rank import ranked
    from stackup.report import SECTIONS
    from stackup.report import format as fmt

    known = facts(comparison)
    ranking = ranked(known.ranking)
    text = write_report(comparison.dataset, tmp_path, scenarios=comparison.scenarios,
                        sensitivity=comparison.sensitivity, tails=comparison.tails).read_text()
    assert all(f"\n## {title}\n" in text for title in SECTIONS)
    fit = _table_rows(text, "Operating clearance: press fit, housing swell and temperature", "scheme")
    assert list(fit) == list(ranking.index)
    film = _table_rows(text, "Loads, oil film and bearing life", "scheme")
    assert list(film) == list(ranking.index)
    for scheme, row in ranking.iterrows():
        mean_std = f"{row.clearance_mean_um:.2f} ± {row.clearance_std_um:.2f}"
        assert fit[scheme]["operating mean ± std [µm]"] == mean_std
        assert film[scheme]["engine life median [h]"] == fmt.significant_triple((row.engine_life_median_h,
                                                                                 *row.engine_life_median_h_ci))
    for scheme, row in known.film.iterrows():
        assert film[scheme]["engine life B10 [h]"] == fmt.significant_triple(row.engine_life_b10_h)
        assert film[scheme]["h_min P5 [µm]"].startswith(f"{row.h_min_p05_um[0]:.2f} [")
    clearance = _table_rows(text, "Clearance per scheme", "scheme")
    for scheme, row in known.clearance.iterrows():
        assert clearance[scheme]["mean [µm]"] == f"{row.mean_um:.2f}"
    first_page = text.split("\n## ")[0]
    decision = _first_table(first_page)
    assert list(decision) == list(ranking.index)
    for scheme, row in ranking.iterrows():
        assert decision[scheme]["outside window [ppm]"].startswith(fmt.interval(
            row.outside_window_ppm, row.outside_window_ppm_ci, fmt.ppm_digits(row.outside_window_ppm)))
        assert decision[scheme]["shell grades"] == str(row.shell_grades)
        assert decision[scheme]["surplus [%]"] == f"{row.surplus_pct:.1f}"
    assert f"**Use {ranking.index[0]}**" in first_page


def _first_table(text, first_column="scheme"):
    """The rows of the first pipe table in ``text``, by their ``first_column`` cell."""
    block = next(b for b in text.split("\n\n") if b.startswith("| "))
    rows = [[c.strip() for c in line.strip().strip("|").split(" | ")] for line in block.splitlines()
            if line.startswith("| ")]
    return {row[rows[0].index(first_column)]: dict(zip(rows[0], row)) for row in rows[1:]}


@pytest.fixture(scope="module")
def report_text(comparison, tmp_path_factory):
    out = tmp_path_factory.mktemp("report")
    return write_report(comparison.dataset, out, scenarios=comparison.scenarios, sensitivity=comparison.sensitivity,
                        tails=comparison.tails).read_text()


def test_the_first_page_is_a_short_verdict_and_the_decision_table(report_text):
    first_page = report_text.split("\n## ")[0]
    verdict = first_page.split("<!-- verdict -->")[1].split("<!-- /verdict -->")[0]
    assert len(verdict.split()) <= 150
    assert "**Model uncertainty:**" in verdict and "**Process scenarios:**" in verdict
    assert "less than 1 ppm apart count as equal (`--negligible`)" in first_page  # the threshold, stated
    table = _first_table(first_page.split("<!-- /verdict -->")[1])
    columns = next(iter(table.values()))
    assert {"outside window [ppm]", "shell grades", "bore + journal grades", "stock-outs [ppm]", "surplus [%]",
            "worst process scenario: outside [ppm]", "worst model uncertainty: outside [ppm]"} <= set(columns)
    assert len(report_text.split()) <= 3500


def test_the_verdict_says_whether_the_choice_holds_under_the_model_uncertainties(comparison):
    from stackup.facts import facts
    from stackup.rank import ranked
    from stackup.report.verdict import verdict

    known = facts(comparison)
    ranking = ranked(known.ranking)
    scenario_rankings = {label: ranked(rows) for label, rows in known.scenario_rankings.items()}
    text = " ".join(verdict(known, ranking, scenario_rankings))
    chosen = ranking.index[0]
    model = [label for label, about in known.scenario_about.items() if about.kind == "model"]

    def beaten(label):  # another scheme puts fewer bearings outside, 95 % intervals apart and >= negligible
        other = scenario_rankings[label]
        lo, hi = other.loc[chosen, "outside_window_ppm_ci"]
        return any(other.loc[s, "outside_window_ppm_ci"][1] < lo and
                   other.loc[chosen, "outside_window_ppm"] - other.loc[s, "outside_window_ppm"] >= 1.0
                   for s in other.index if s != chosen)

    flips = [label for label in model if beaten(label)]
    if flips:
        assert "the choice changes within the declared ranges" in text and "Measure " in text
        assert f"with {flips[0]}, **" in text or any(f"with {label}, **" in text for label in flips)
    else:
        assert "it stays first over the declared ranges of the housing stiffness" in text
    # a scenario the counts cannot resolve (the chosen scheme's share within the others' intervals) is no flip
    for label in model:
        if label not in flips:
            assert f"with {label}, **" not in text


def test_a_difference_the_scenario_counts_cannot_resolve_does_not_break_the_choice():
    from stackup.report.verdict import _flips, clearance_level
    from stackup.rank import ranked

    from stackup.facts import RankingRows

    def _rows(**schemes):
        return RankingRows({name: {"outside_window_ppm": share, "outside_window_ppm_ci": ci, "shell_grades": grades,
                                   "part_grades": 6, "stockout_ppm": stockouts, "surplus_pct": 9.0,
                                   "outside_window_source": "counted"}
                            for name, (share, ci, grades, stockouts) in schemes.items()}, {}, (34.5e-6, 57.5e-6), {})

    # under the scenario the chosen scheme counts 20 ppm [1, 112], the other 0 [0, 74]: level on the clearance,
    # the other first on cost alone: not a flip; 781 ppm [700, 870] against 0 [0, 74]: a flip
    level = ranked(_rows(chosen=(20.0, (1.0, 112.0), 4, 840.0), other=(0.0, (0.0, 74.0), 3, 0.0)))
    apart = ranked(_rows(chosen=(781.0, (700.0, 870.0), 4, 840.0), other=(0.0, (0.0, 74.0), 3, 0.0)))
    assert level.index[0] == "other" and clearance_level(level, 1.0) == {"chosen", "other"}
    flips = _flips(["level", "apart"], {"level": level, "apart": apart}, "chosen", 1.0)
    assert flips == [("apart", ["other"])] and clearance_level(apart, 1.0) == {"other"}


def test_schemes_appear_in_one_order_in_every_table(report_text, comparison):
    from stackup.rank import rank

    order = list(rank(comparison).index)
    for block in report_text.split("\n\n"):
        if not block.startswith("| "):
            continue
        rows = [[c.strip() for c in line.strip().strip("|").split(" | ")] for line in block.splitlines()[2:]]
        names = [cell for row in rows for cell in row[:2] if cell in order]
        if names:
            assert names == [n for n in order if n in names], block.splitlines()[0]
        head = [c.strip() for c in block.splitlines()[0].strip("|").split(" | ")]
        in_head = [c for c in head if c in order]
        assert in_head == [n for n in order if n in in_head]


def test_the_text_has_no_doubled_punctuation(report_text):
    import re

    prose = "\n".join(line for line in report_text.splitlines() if not line.startswith(("|", "```", "![")))
    for pattern in (r"\.\.(?!\.)", r"\.;", r";\.", r",\.", r"\.,", r" ,", r" \.(?!\d)", r"\S  +\S", r"\(\s*\)"):
        assert not re.search(pattern, prose), (pattern, re.search(pattern, prose))


def test_a_bore_process_that_scraps_blocks_reaches_the_first_page(tmp_path):
    from stackup.engines import engine_path
    from stackup.study import Study

    text = engine_path("iso-example").read_text().replace(
        '[housing_bore]\nlimits = [50.000, 50.018]\nprocess = { distribution = "normal", cpk = 1.33 }',
        '[housing_bore]\nlimits = [50.000, 50.018]\nprocess = { distribution = "normal", cpk = 0.5 }')
    path = tmp_path / "wide-bores.toml"
    path.write_text(text.replace('name = "iso-example"', 'name = "wide-bores"'))
    ds = Study(engine=str(path), schemes=("iso13778-3",), n_engines=300, mechanics_engines=0, progress=False,
               pilot_engines=1000).run()
    first = write_report(ds, tmp_path / "report").read_text().split("<!-- /verdict -->")[0]
    blocks = (ds.status.values == 1).mean()
    assert blocks > 0.4  # most blocks have a bore outside its limits at C_pk 0.5
    assert "**Check first:**" in first and f"{100 * blocks:.0f} % of the blocks are scrapped" in first


def test_a_share_below_the_precision_never_reads_as_zero():
    from stackup.report import format as fmt

    assert fmt.ppm(2e-7, (0.0, 1e-6)) == "< 0.001 ppm [0, < 0.001]"  # not "0.000 ppm [0.000, 0.000]"
    assert fmt.ppm(0.0, (0.0, 0.0)) == "0 ppm" and fmt.ppm_interval(0.0, (0.0, 74.0)) == "0 [0, 74]"
    assert fmt.ppm(0.05, (0.034, 0.065)) == "0.050 ppm [0.034, 0.065]"
    assert fmt.ppm_interval(11831.0, (10901.0, 12818.0)) == "11831 [10901, 12818]"
    assert fmt.ppm(59333.0, (51146.0, 68393.0)) == "59,333 ppm [51,146, 68,393]"


def test_a_long_source_is_cited_by_its_title():
    from stackup.report.format import cited

    long = ("MAHLE Clevite, How much clearance do your bearings need?: 0.00075-0.0010 in of clearance per inch of "
            "journal diameter as the starting point for most applications, 0.0005 in more at the top for highly "
            "loaded engines.")
    assert cited(long) == "MAHLE Clevite, How much clearance do your bearings need?"
    short = "assumed: journals run 10-20 K above their bulkheads"
    assert cited(short + ".") == short  # short enough: whole, without its full stop
    words = " ".join(["word"] * 40)
    assert cited(words) == " ".join(["word"] * 30) + " …"
    # a citation is never cut inside its brackets: the first sentence then
    source = ("Rozhdestvensky et al. 2018, Tribology in Industry 40 (Table 1: bearing diameter, width, clearance, "
              "speed; cylinder bore and stroke). Part processes, spans, masses, section inertias and the pressure "
              "model are assumptions of typical size for such an engine.")
    assert cited(source) == ("Rozhdestvensky et al. 2018, Tribology in Industry 40 (Table 1: bearing diameter, width, "
                             "clearance, speed; cylinder bore and stroke)")


def test_doubled_misalignment_lengthens_no_life_at_any_position(comparison, tmp_path):
    from stackup.facts import facts

    positions, engines = facts(comparison).life_changes["misalignment ×2"]
    # paired on the same engines: no position's median life rises beyond its 95 % interval, and the engines' lives
    # (their weakest bearing's) fall
    assert all(change[1] <= 0 for change in positions.life_change_h)
    assert all(change[0] < 0 for change in engines.engine_life_change_h)
    text = write_report(comparison.dataset, tmp_path, scenarios=comparison.scenarios,
                        sensitivity=comparison.sensitivity, tails=comparison.tails).read_text()
    assert "**Lives** under the scenarios that ran the films (12+ paired engines)" in text
    assert "| misalignment ×2 | " in text and " | none |" in text


def test_with_the_film_over_the_surface_the_report_says_where_edges_run_below_the_critical_film(tmp_path):
    # tilt_method coupled: which positions, over how much of the cycle, how thin, at what load and crank angle,
    # read from the dataset; α and the lives read that film (with the mid-plane film they ignore the contact)
    from stackup.facts.mechanics import edge_contact
    from stackup.film.cycle import FILM_STATUS
    from stackup.study import Study

    ds = Study(engine="rozhdestvensky-4", schemes=("iso13778-1",), n_engines=300, mechanics_engines=4,
               pilot_engines=1000, crank_angle_step=4.0, tilt_method="coupled", progress=False).run()
    edge = edge_contact(ds)
    assert edge.surface and edge.critical == pytest.approx(1.9e-6)
    text = write_report(ds, tmp_path).read_text()
    touching = ds.film_status.values == FILM_STATUS.index("edge_contact")
    if edge.touching:
        b = int(edge.per_position.index[0])
        on = touching[..., b - 1]
        film = float(np.median(ds.h_min.values[..., b - 1][on]))
        assert f"bearing {b} (" in text and f"{1e6 * film:.2f} µm at up to" in text
        assert "α and the lives read it" in text and "do not count" not in text
    else:
        assert "runs below h_lim,cr" not in text
    assert "Minimum film over the bearing surface" in text


def test_with_the_default_tilt_the_report_says_where_edges_reach_the_wall_and_the_lives_count_them(tmp_path):
    # tilt_method equilibrium: each journal turned back at its own support; which positions reach the wall, over
    # how much of the cycle, at what load and crank angle, read from the dataset; α and the lives read that film
    from stackup.facts.mechanics import edge_contact
    from stackup.film.cycle import FILM_STATUS
    from stackup.study import Study

    ds = Study(engine="iso-example", schemes=("iso13778-3",), n_engines=300, mechanics_engines=4,
               pilot_engines=1000, crank_angle_step=4.0, progress=False).run()
    edge = edge_contact(ds)
    assert not edge.surface and edge.counted and edge.touching
    on = ds.film_status.values == FILM_STATUS.index("edge_contact")
    assert np.all(ds.h_min.values[on] < ds.h_min_midplane.values[on])  # the film over the width, at the wall
    assert np.all(np.isfinite(ds.edge_contact_load.values[on])) and np.all(np.isnan(ds.edge_contact_load.values[~on]))
    assert np.all(ds.alpha.values[on] >= ds.edge_contact_share.values[on])
    text = write_report(ds, tmp_path).read_text()
    b = int(edge.per_position.index[0])
    load = float(np.nanmedian(ds.edge_contact_load.values[..., b - 1][on[..., b - 1]]))
    assert f"reaches the wall: bearing {b} (" in text and f"{load / 1e3:.1f} kN" in text
    assert "α and the lives read it" in text and "do not count" not in text


def test_with_the_film_over_the_surface_the_report_says_whether_the_tolerances_change_the_edge_contact(tmp_path):
    # the doubled-misalignment scenario on the same engines (common random numbers): each engine's share of the
    # cycle below h_lim,cr against itself, per position, for the first-ranked scheme; and the unresolved share
    from stackup.facts import facts
    from stackup.study import Study

    study = Study(engine="rozhdestvensky-4", schemes=("iso13778-1",), n_engines=300, mechanics_engines=6,
                  pilot_engines=1000, crank_angle_step=4.0, tilt_method="coupled", progress=False)
    ds = study.run()
    doubled = replace(study, scenario={"misalignment_scale": 2.0}).run()
    positions, _ = facts(ds, scenarios={"misalignment ×2": doubled}).life_changes["misalignment ×2"]
    changes = np.array([v[0] for v in positions.edge_share_change_pts])
    direct = np.median(100 * (doubled.edge_contact_share.values[0] - ds.edge_contact_share.values[0]), axis=0)
    np.testing.assert_allclose(changes, direct)
    text = write_report(ds, tmp_path, scenarios={"misalignment ×2": doubled}).read_text()
    assert ("With coaxiality and run-out ×2 (misalignment ×2, 6 paired engines) iso13778-1's share of the cycle "
            "with an edge below h_lim,cr changes by") in text
    assert "`tilt_unresolved`" in text or not np.nanmax(ds.tilt_unresolved.values) > 0


def test_the_tolerance_sentence_reads_right_for_no_change_and_for_a_study_without_edge_contact():
    # no "−0.0 points" and "does not change" where every median is zero; the sentence (and the march's unresolved
    # share) also where no edge touches in the study itself: the doubled misalignment may make some
    from types import SimpleNamespace

    import pandas as pd

    from stackup.facts.mechanics import EdgeContact, FilmOutcomes
    from stackup.report.mechanics import _outcomes_text, _tolerance_text

    def facts_with(changes):
        index = pd.MultiIndex.from_tuples([("s", b) for b in (1, 2, 3)], names=["scheme", "bearing"])
        positions = pd.DataFrame({"pairs": [12] * 3, "edge_share_change_pts": [(c, c - 1, c + 1) for c in changes]},
                                 index=index)
        edge = EdgeContact(300, 0, [0.0], [], 0.005, surface=True, critical=1.9e-6, per_position=pd.DataFrame(),
                           periodic=1.0, unresolved=(0.1, 0.2))
        return SimpleNamespace(misalignment=("misalignment ×2", 2.0), edge=edge,
                               life_changes={"misalignment ×2": (positions, None)})

    none = _tolerance_text(facts_with([0.0, -0.04, 0.03]), ["s"])
    assert "share of the cycle with an edge below h_lim,cr does not change (median per position, bearings 1–3)" in none
    assert "−0.0" not in none and "within its 95 % interval of zero everywhere" in none
    some = _tolerance_text(facts_with([-0.4, 2.04, 0.0]), ["s"])
    assert "changes by −0.4 to +2.0 points" in some
    facts = facts_with([1.0, 2.0, 3.0])
    text = " ".join(_outcomes_text(FilmOutcomes(300, {}, 0, 300, 0), facts.edge, _tolerance_text(facts, ["s"])))
    assert "With coaxiality and run-out ×2" in text and "`tilt_unresolved`" in text


def test_where_edges_reach_the_wall_the_report_says_whether_alpha_and_the_lives_count_them():
    """A study whose α and lives read the film over the width (h_min below h_min_midplane) counts the edges at the
    wall; one saved when they read the mid-plane does not, and the report names the method that counts them."""
    import xarray as xr

    from stackup.facts.mechanics import FilmOutcomes, edge_contact
    from stackup.report.mechanics import _outcomes_text
    from stackup.study.schema import FILM_STATUS_FLAGS, TILT_STATUS_FLAGS

    def flags(meanings):
        return {"flag_values": list(range(len(meanings))), "flag_meanings": " ".join(meanings)}

    def study(h_min):
        status = np.array([[[FILM_STATUS_FLAGS.index(s) for s in ("edge_contact", "periodic")]]], np.int8)
        dims = ("scheme", "mech_engine", "bearing")
        not_computed = np.full((1, 1, 2), TILT_STATUS_FLAGS.index("not_computed"), np.int8)
        return xr.Dataset({"film_status": (dims, status, flags(FILM_STATUS_FLAGS)),
                           "film_valid": (dims, np.ones((1, 1, 2), bool)),
                           "edge_contact_share": (dims, [[[0.08, 0.0]]]), "h_min": (dims, [h_min]),
                           "h_min_midplane": (dims, [[[2e-6, 3e-6]]]),
                           "edge_contact_load": (dims, [[[31e3, np.nan]]]),
                           "edge_contact_angle": (dims, [[[372.0, np.nan]]]),
                           "tilt_status": (dims, not_computed, flags(TILT_STATUS_FLAGS))},
                          coords={"scheme": ["s"], "bearing": [1, 2]})

    outcomes = FilmOutcomes(2, {}, 0, 1, 1)
    counted = " ".join(_outcomes_text(outcomes, edge_contact(study([[0.1e-6, 3e-6]]))))
    assert "α and the lives read it" in counted and "do not count" not in counted
    assert "`--tilt-method coupled`" in counted
    assert "reaches the wall: bearing 1 (8.0 %–8.0 % of the cycle; 0.10 µm at up to 31.0 kN near 372°)" in counted
    midplane = " ".join(_outcomes_text(outcomes, edge_contact(study([[2e-6, 3e-6]]))))
    assert "do not count" in midplane and "`--tilt-method coupled`" in midplane


def test_lives_that_rise_with_their_film_are_counted_and_those_without_it_named():
    import pandas as pd

    from stackup.report.sections import _life_change_row

    index = pd.MultiIndex.from_tuples([("a", 1), ("a", 2), ("b", 1), ("b", 2)], names=["scheme", "bearing"])
    positions = pd.DataFrame({"pairs": [50] * 4,
                              "life_change_h": [(600.0, 400.0, 800.0), (-5.0, -20.0, 10.0), (900.0, 700.0, 1100.0),
                                                (300.0, 100.0, 500.0)],
                              "h_min_mean_change_um": [(0.3, 0.2, 0.4), (0.0, -0.1, 0.1), (0.4, 0.3, 0.5),
                                                       (-0.1, -0.2, 0.0)],
                              "h_min_change_um": [(-0.5, -0.6, -0.4), (0.0, -0.1, 0.1), (0.2, 0.1, 0.3),
                                                  (-0.1, -0.2, 0.0)]}, index=index)
    engines = pd.DataFrame({"engine_life_change_h": [(550.0, 300.0, 800.0), (280.0, 90.0, 470.0)]},
                           index=pd.Index(["a", "b"], name="scheme"))
    row = _life_change_row("support tilt compliance ×2", positions, engines, "a")
    rises = row["lives that rise"]
    # bearing 1 of a: a thicker mean, a thinner minimum (method 1's direction), said; bearing 1 of b: both thicker
    assert rises.startswith("2 of 4 (+600 to +900 h): cycle-mean film +0.30 to +0.40 µm, cycle minimum −0.50 µm "
                            "at 1 (method 1 reads the mean)")
    assert "bearing 2 of b (+300 h; cycle-mean film −0.10 µm)" in rises and "bearing 1 of a" not in rises
    assert row["per position [h]"] == "−5 (bearing 2) to +600" and row["per engine [h]"] == "+550"


def test_where_method_1_reads_a_film_below_the_critical_film_the_report_says_its_hours_are_no_margin():
    from types import SimpleNamespace

    import pandas as pd

    from stackup.report.mechanics import _method1_range_text

    index = pd.MultiIndex.from_tuples([("s", 1), ("s", 2), ("s", 3)], names=["scheme", "bearing"])
    corrected = pd.DataFrame({"h_min_mean_corrected": [(4.0e-6, 3.5e-6, 4.5e-6), (1.6e-6, 1.5e-6, 1.7e-6),
                                                       (1.85e-6, 1.8e-6, 1.9e-6)]}, index=index)
    facts = SimpleNamespace(study=SimpleNamespace(life_film="cycle-mean"), corrected=corrected,
                            limits=SimpleNamespace(critical_film=1.9e-6), bearings=pd.DataFrame())
    text = " ".join(_method1_range_text(facts, "s"))
    assert "At bearings 2 and 3 s's cycle-mean film, the film method 1 reads, is 1.60 / 1.85 µm, below" in text
    assert "no film margin" in text
    # no check: the study's own medians per position; all above h_lim,cr: nothing said
    bearings = pd.DataFrame({"h_min_mean_median_um": [(5.0, 4.0, 6.0), (2.5, 2.0, 3.0), (3.0, 2.5, 3.5)]},
                            index=index)
    assert _method1_range_text(SimpleNamespace(**{**vars(facts), "corrected": pd.DataFrame(),
                                                  "bearings": bearings}), "s") == []


def test_a_metric_the_same_for_every_scheme_is_named_with_its_unit():
    import pandas as pd

    from stackup.report.sections import non_discriminating

    ranking = pd.DataFrame({"alpha_over_limit_pct": [100.0, 100.0],
                            "alpha_over_limit_pct_ci": [(98.8, 100.0), (98.8, 100.0)]}, index=["a", "b"])
    text = non_discriminating(ranking)[0]
    assert text == ("Boundary friction over 20 % of the cycle (100 % of the bearings for every scheme) does not "
                    "separate the schemes here.")
    # a plural name alone takes a plural verb
    ranking = pd.DataFrame({"life_below_target_pct": [0.0, 0.0],
                            "life_below_target_pct_ci": [(0.0, 1.2), (0.0, 1.2)]}, index=["a", "b"])
    assert non_discriminating(ranking)[0] == ("Lives below the target (none in any scheme) do not separate the "
                                              "schemes here.")


def test_positions_where_a_stray_bearing_reaches_the_wall_are_counted_not_described():
    import pandas as pd

    from stackup.facts.mechanics import EdgeContact, FilmOutcomes
    from stackup.report.mechanics import _outcomes_text

    rows = pd.DataFrame({"touching_pct": [0.2, 100.0, 3.0], "cycle_share": [0.02, 0.08, 0.01],
                         "cycle_lo": [0.0, 0.07, 0.0], "cycle_hi": [0.0, 0.11, 0.0], "film": [0.14e-6, 0.11e-6, 0.1e-6],
                         "load": [4.5e3, 2.3e3, 3e3], "angle": [76.0, 122.0, 80.0]}, index=[1, 2, 5])
    edge = EdgeContact(300, 120, [40.0], [0.08], 0.005, per_position=rows)
    text = " ".join(_outcomes_text(FilmOutcomes(300, {}, 0, 180, 120), edge))
    assert "reaches the wall: bearing 2 (7.0 %–11 % of the cycle" in text and "bearing 1 (" not in text
    assert "; at 2 other positions in under 5 % of the bearings. There the rigid film" in text


def test_an_edge_that_reaches_the_wall_in_few_bearings_at_every_position_is_counted_not_described():
    # the marched tilt keeps most edges off the wall: a few bearings at a few positions, none of them described
    import pandas as pd

    from stackup.facts.mechanics import EdgeContact, FilmOutcomes
    from stackup.report.mechanics import _outcomes_text

    rows = pd.DataFrame({"touching_pct": [1.0, 0.7], "cycle": [0.01, 0.01], "cycle_lo": [0.0, 0.0],
                         "cycle_hi": [0.0, 0.0], "film": [1e-7, 1e-7], "load": [2e3, 2e3], "angle": [120.0, 480.0]},
                        index=pd.Index([2, 4], name="bearing"))
    edge = EdgeContact(computed=10465, touching=32, per_scheme_pct=[0.3], per_position_share=[0.01, 0.01],
                       floor=0.005, per_position=rows)
    text = _outcomes_text(FilmOutcomes(10465, {}, 0, 10433, 32), edge)[0]
    assert ("In 32 of them (0.3 %) a tilted journal's edge reaches the wall: at 2 positions, each in under 5 % of "
            "the bearings. There") in text
    assert ": ;" not in text and "bearing 2 (" not in text
