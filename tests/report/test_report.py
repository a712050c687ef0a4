"""The report is a function of saved datasets alone: no sampling, no backend change, full or summary datasets.

The report's words are :mod:`stackup.report.templates`: the tests find a sentence by its template filled with the
numbers of the facts (:func:`sentence`), never by prose copied here, so a rewording breaks no test while a wrong
number or a missing sentence does. The exact first page of one comparison is a snapshot
(``test_report_snapshots.py``).
"""

import json
import re
import string
import subprocess
import sys
import tomllib
from dataclasses import replace

import numpy as np
import pytest
from small_runs import SCENARIOS, STUDY

import stackup
import stackup.schemes as schemes
from stackup.io import open_comparison, save_comparison
from stackup.report import SECTIONS, clearance_summary, fit_summary, write_report
from stackup.report import format as fmt
from stackup.report import templates as words

KW = STUDY  # the integration tier's shared comparison (tests/small_runs.py, tests/conftest.py)


@pytest.fixture(scope="module")
def comparison(small_comparison):
    """The shared comparison, with the declared model uncertainties, as saved and opened again."""
    return small_comparison.comparison


def sentence(template, **fields):
    """A pattern of the report's sentence ``template`` (a :mod:`stackup.report.templates` constant) as filled.

    Each field given in ``fields`` is written as the template writes it (its format spec applied); any other
    field matches any text within the line, captured under its name (``match["changes"]``). Templates compose:
    ``words.EDGE_COUNTED.replace("{positions}", words.EDGE_POSITION_PART + "{positions}")`` is the sentence whose
    positions begin with that position.
    """
    pattern = []
    for literal, name, spec, _ in string.Formatter().parse(template):
        pattern.append(re.escape(literal))
        if name is None:
            continue
        if name in fields:
            pattern.append(re.escape(format(fields[name], spec)))
        elif f"(?P<{name}>" in "".join(pattern):  # a field the template writes twice: the same text again
            pattern.append(f"(?P={name})")
        else:
            pattern.append(f"(?P<{name}>[^\\n]*?)")
    return re.compile("".join(pattern))


def edge_sentence(template, **fields):
    """:func:`sentence` of an edge-contact ``template`` whose positions begin with :data:`EDGE_POSITION_PART`
    (its fields ``bearing``, ``lo``, ``hi``, ``film``, ``load``, ``angle`` among ``fields``)."""
    return sentence(template.replace("{positions}", words.EDGE_POSITION_PART + "{positions}"), **fields)


def heading(title):
    """The line of a section's heading (``title`` one of :data:`stackup.report.SECTIONS`)."""
    assert title in SECTIONS
    return words.SECTION.format(title=title)


def section_text(text, title):
    """The body of the section ``title`` of the report ``text`` (up to the next heading)."""
    return text.split(heading(title) + "\n")[1].split("\n## ")[0]


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
    # the exact file keeps every engine: the plan is written, not asked for
    planning = section_text(text, "Planning: shells per grade")
    chosen = list(stackup.rank(saved).index)[0]
    assert sentence(words.PLAN, scheme=chosen).search(planning) and words.PLAN_NEEDS_ENGINES not in planning
    assert "| misalignment ×2 |" in section_text(text, "Scenarios")



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
    """The verdict of a study dataset alone (no scenarios), as one text, and the ranking it judged."""
    from stackup.facts import facts
    from stackup.rank import ranked
    from stackup.report.verdict import verdict

    known = facts(ds, **ranking)
    return " ".join(verdict(known, ranked(known.ranking), {})), ranked(known.ranking)


def test_the_verdict_says_when_no_scheme_meets_the_window(comparison):
    ds = comparison.dataset
    text, ranking = _verdict(ds, window=(1e-6, 2e-6))
    best = fmt.ppm(np.nanmin(ranking.outside_window_ppm))
    # the first thing to check, with the window and the best scheme's share outside it
    assert words.CHECK_FIRST.format(notes=words.NOT_MET.format(lo=fmt.um_edge(1e-6), hi=fmt.um_edge(2e-6),
                                                                best=best)) in text
    text, _ = _verdict(ds)
    assert not sentence(words.NOT_MET).search(text)


def test_the_verdict_says_how_much_of_the_cycle_journal_edges_touch_where_most_bearings_do(comparison):
    from stackup.study.schema import flag

    ds = comparison.dataset
    status = ds.film_status.values
    computed = (status != flag(ds.film_status, "not_computed")) & ds.film_valid.values
    touching = computed & (status == flag(ds.film_status, "edge_contact"))
    text, _ = _verdict(ds)
    notes = (words.EDGE_NOTE, words.EDGE_COUNTED_NOTE, words.EDGE_SURFACE_NOTE)
    assert bool(sentence(words.EDGE_COUNTED_NOTE).search(text)) == (touching.sum() >= 0.5 * computed.sum())
    # every bearing touching: said on the first page, with what α and the lives make of it (they read that film)
    edged = ds.copy()
    edged["film_status"] = edged.film_status.where(~computed, flag(ds.film_status, "edge_contact"))
    text, _ = _verdict(edged)
    assert sentence(words.CHECK_FIRST).search(text)
    assert words.EDGE_COUNTED_NOTE.format(share=fmt.percent(1.0)) in text
    # a study saved when α and the lives read the mid-plane film: they ignore the contact, and the page says so
    midplane = edged.copy()
    midplane["h_min"] = midplane.h_min_midplane
    text, _ = _verdict(midplane)
    assert words.EDGE_NOTE.format(share=fmt.percent(1.0)) in text
    assert not sentence(words.EDGE_COUNTED_NOTE).search(text)
    # none touching: nothing said
    clear = ds.copy()
    clear["film_status"] = clear.film_status.where(~computed, flag(ds.film_status, "periodic"))
    text, _ = _verdict(clear)
    assert not any(sentence(note).search(text) for note in notes)


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
    cap = wear["method1_wear_limit_m"] / wear["wear_rate_m_per_s"] / 3600
    assert wear["method1_wear_limit_m"] / wear["wear_rate_m_per_s"] == pytest.approx(1e8)  # the paper's results' scale
    assert sentence(words.LIFE_BIAS_PART, error=100 * error, film=fmt.um(h), ratio=life[0] / life[1],
                    thinner_film=fmt.um(h / (1 + error)), cap=fmt.whole(cap)).search(text)
    # a study without the tier's measured errors says nothing of it
    bare = ds.copy()
    bare.attrs = {k: v for k, v in ds.attrs.items() if k != "film_method_errors"}
    assert not sentence(words.LIFE_BIAS_PART).search(" ".join(limits_of_validity(facts(bare))))


def test_the_film_section_gives_the_heat_balance_of_the_bearings(comparison, tmp_path):
    from stackup.facts.declared import Processes
    from stackup.study.schema import flag

    ds = comparison.dataset
    text = section_text(write_report(ds, tmp_path).read_text(), "Loads, oil film and bearing life")
    valid = (ds.film_status.values != flag(ds.film_status, "not_computed")) & ds.film_valid.values
    temperature = np.percentile(ds.film_temperature.values[valid], [5, 50, 95])
    supply = Processes.of(ds).crank.oil_supply_temperature_degC
    assert sentence(words.HEAT, temperature=f"{temperature[0]:.0f}-{temperature[2]:.0f}",
                    temperature_median=f"{temperature[1]:.0f}",
                    supply=words.SUPPLY_PART.format(supply=supply)).search(text)


def test_report_reads_limits_and_life_target_from_the_dataset(comparison, tmp_path):
    ds = comparison.dataset.assign(design_contact_pressure_min=20e6, design_shell_stress_max=300e6,
                                   life_target=1e9 * 3600)
    text = write_report(ds, tmp_path).read_text()
    # a check no bearing fails is said in a sentence, not as a column of zeros
    assert "p < 20 MPa [ppm]" in text or words.FIT_LOW_PRESSURE.format(pressure=20) in text
    assert "σ > 300 MPa [ppm]" in text or words.FIT_HIGH_STRESS.format(stress=300) in text
    assert words.SHORT_COLUMN.format(target=1e9) in text


def test_report_of_streaming_summaries_agrees_and_says_what_needs_every_engine(tmp_path):
    from dataclasses import replace

    full = stackup.Study(**KW).run()
    summary = replace(stackup.Study(**KW), keep="summaries").run()
    text = write_report(summary, tmp_path).read_text()
    assert section_text(text, "Planning: shells per grade").strip() == words.PLAN_NEEDS_ENGINES
    assert section_text(text, "What drives the spread").strip() == words.NO_SENSITIVITY
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
    section = section_text(report, "Designed scheme")
    ranks = stackup.rank(comparison)["rank"]
    against = (words.DESIGN_AGAINST_PART.format(outcome=words.DESIGN_OUTCOME_PART.format(rank=ranks[design["start"]]),
                                                start=design["start"]) if design["start"] in ranks else
               words.DESIGN_START_ABSENT_PART.format(start=design["start"]))
    assert sentence(words.DESIGNED, name="designed", evaluations=fmt.count(design["evaluations"]),
                    start=design["start"], outcome=words.DESIGN_OUTCOME_PART.format(rank=ranks["designed"]),
                    against=against).search(section)
    assert "| housing bore |" in section  # the grades of each dimension, side by side


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
    stated = words.NONE_STATED.format(worst=fmt.um_range(summary.worst_case_min_um["unstated"],
                                                         summary.worst_case_max_um["unstated"]))
    row = next(line for line in report.splitlines() if line.startswith(f"| unstated | {stated} |"))
    assert row.rstrip(" |").endswith("—")


def test_a_study_without_the_mechanical_chain_says_so(tmp_path):
    from stackup.facts import Run
    from stackup.report.verdict import run_notes
    from stackup.study import Study

    ds = Study(schemes=("iso13778-4",), n_engines=200, mechanics_engines=0, progress=False, pilot_engines=1000).run()
    said = words.NO_MECHANICS_NOTE.format(reason=words.NONE_ASKED_PART)
    assert said in run_notes(Run.of(ds))
    assert said in write_report(ds, tmp_path).read_text().split("<!-- /verdict -->")[0]


def test_numbers_are_written_one_way():
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

    known = facts(comparison)
    ranking = ranked(known.ranking)
    text = write_report(comparison.dataset, tmp_path, scenarios=comparison.scenarios,
                        sensitivity=comparison.sensitivity, tails=comparison.tails).read_text()
    assert all(f"\n{heading(title)}\n" in text for title in SECTIONS)
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
    chosen = ranking.iloc[0]
    clearance = words.CLEARANCE_PART.format(mean=chosen.clearance_mean_um, std=chosen.clearance_std_um)
    assert any(sentence(use, scheme=ranking.index[0], clearance=clearance).search(first_page)
               for use in (words.USE_ONLY, words.USE_CLEARANCE, words.USE_COST, words.USE_INTERFERENCE))


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
    assert any(sentence(t).search(verdict) for t in (words.MODEL_HOLDS, words.MODEL_BREAKS))
    assert any(sentence(t).search(verdict) for t in (words.PROCESS_HOLDS, words.PROCESS_BREAKS))
    assert sentence(words.SUBTITLE, negligible=fmt.general(1.0)).search(first_page)  # the threshold, stated
    table = _first_table(first_page.split("<!-- /verdict -->")[1])
    columns = next(iter(table.values()))
    assert {"outside window [ppm]", "shell grades", "bore + journal grades", "stock-outs [ppm]", "surplus [%]",
            words.WORST_PROCESS, words.WORST_MODEL} <= set(columns)
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
        assert sentence(words.MODEL_BREAKS).search(text)
        assert any(sentence(words.MODEL_FLIP_PART, scenario=label).search(text) for label in flips)
    else:
        inputs = list(dict.fromkeys(known.scenario_about[label].input for label in model))  # each declared range
        assert sentence(words.MODEL_HOLDS, inputs=words.listed(inputs)).search(text)
    # a scenario the counts cannot resolve (the chosen scheme's share within the others' intervals) is no flip
    for label in model:
        if label not in flips:
            assert not sentence(words.MODEL_FLIP_PART, scenario=label).search(text)


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
    assert sentence(words.CHECK_FIRST).search(first) and words.BLOCKS_LOST.format(share=fmt.percent(blocks)) in first


def test_a_share_below_the_precision_never_reads_as_zero():
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
    chosen = list(stackup.rank(comparison).index)[0]
    pairs = int(positions.xs(chosen, level="scheme").pairs.min())
    assert pairs == KW["mechanics_engines"]
    intro = sentence(words.SCENARIO_LIVES_INTRO, pairs=pairs, scheme=chosen).search(text)
    assert intro
    lives = _first_table(text[intro.end():], "scenario")  # the table under it
    assert lives["misalignment ×2"][words.LIVES_RISE_COLUMN] == words.LIVES_NONE_RISE


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
    critical = fmt.um(edge.critical, 2)
    if edge.touching:
        b = int(edge.per_position.index[0])
        on = touching[..., b - 1]
        film = float(np.median(ds.h_min.values[..., b - 1][on]))
        # α and the lives read the film over the surface there (not the mid-plane's, which does not count it)
        assert edge_sentence(words.EDGE_SURFACE, critical=critical, bearing=b,
                             film=fmt.fixed(1e6 * film, 2)).search(text)
        assert not sentence(words.EDGE_CYCLES).search(text)
    else:
        assert not sentence(words.EDGE_SURFACE).search(text)
    assert sentence(words.FILM_INTRO, where=words.SURFACE_PART, critical=critical).search(text)


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
    # α and the lives read the film at the wall (not the mid-plane's, which does not count it)
    assert edge_sentence(words.EDGE_COUNTED, bearing=b, load=fmt.fixed(load / 1e3, 1)).search(text)
    assert not sentence(words.EDGE_CYCLES).search(text)


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
    said = sentence(words.EDGE_TOLERANCE, factor="2", label="misalignment ×2", pairs=6, scheme="iso13778-1",
                    contact=words.BELOW_CRITICAL, first=int(ds.bearing.min()), last=int(ds.bearing.max())).search(text)
    assert said
    rounded = np.round(changes, 1) + 0.0
    assert rounded.any()  # the doubled tolerances change the contact: by how much, said
    assert said["changes"] != words.EDGE_TOLERANCE_NONE
    assert fmt.signed(rounded.min(), 1) in said["changes"] and fmt.signed(rounded.max(), 1) in said["changes"]
    assert sentence(words.EDGE_UNRESOLVED).search(text) or not np.nanmax(ds.tilt_unresolved.values) > 0


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

    sentence_of = dict(factor="2", label="misalignment ×2", pairs=12, scheme="s", contact=words.BELOW_CRITICAL,
                       first=1, last=3)
    none = _tolerance_text(facts_with([0.0, -0.04, 0.03]), ["s"])
    assert none == words.EDGE_TOLERANCE.format(**sentence_of, changes=words.EDGE_TOLERANCE_NONE,
                                               beyond=words.EDGE_TOLERANCE_WITHIN)
    assert "−0.0" not in none
    some = _tolerance_text(facts_with([-0.4, 2.04, 0.0]), ["s"])
    # bearing 2's interval (+1.04, +3.04) is clear of zero
    said = sentence(words.EDGE_TOLERANCE, **sentence_of,
                    beyond=words.EDGE_TOLERANCE_BEYOND.format(s="", bearings=2)).fullmatch(some)
    assert said and re.fullmatch(r"\D*−0\.4\D+\+2\.0\D*", said["changes"])  # from the least to the most, rounded
    facts = facts_with([1.0, 2.0, 3.0])
    text = " ".join(_outcomes_text(FilmOutcomes(300, {}, 0, 300, 0), facts.edge, _tolerance_text(facts, ["s"])))
    assert sentence(words.EDGE_TOLERANCE, **sentence_of).search(text)
    assert sentence(words.EDGE_UNRESOLVED, median=fmt.percent(0.1), high=fmt.percent(0.2)).search(text)


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
    # α and the lives read the film at the wall; the position as the dataset has it
    assert sentence(words.EDGE_COUNTED, edge=1, share="50 %", positions=words.EDGE_POSITION_PART.format(
        bearing=1, lo="8.0 %", hi="8.0 %", film="0.10", load="31.0", angle="372"), others="").search(counted)
    assert not sentence(words.EDGE_CYCLES).search(counted)
    midplane = " ".join(_outcomes_text(outcomes, edge_contact(study([[2e-6, 3e-6]]))))
    # they read the mid-plane film: the contact is not counted, and the method that counts it is named
    assert sentence(words.EDGE_CYCLES, edge=1).search(midplane)
    assert not sentence(words.EDGE_COUNTED).search(midplane)


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
    rises = row[words.LIVES_RISE_COLUMN]
    # bearing 1 of a: a thicker mean, a thinner minimum (method 1's direction), said; bearing 1 of b: both thicker
    thinner = words.LIVES_RISE_THINNER_MINIMUM.format(span="−0.50", where=words.LIVES_RISE_THINNER_AT.format(count=1))
    assert rises.startswith(words.LIVES_RISE_WITH_FILM.format(count=2, total=4, lo="+600", hi="+900", film_lo="+0.30",
                                                              film_hi="+0.40", minimum=thinner))
    # bearing 2 of b rises with a thinner film: named; bearing 1 of a (with its film) is not
    assert words.LIVES_RISE.format(where=words.LIFE_RISE_PART.format(bearing=2, scheme="b", change="+300",
                                                                     film="−0.10")) in rises
    assert not sentence(words.LIFE_RISE_PART, bearing=1, scheme="a").search(rises)
    assert row[words.LIVES_POSITION_COLUMN] == words.LIVES_SPAN.format(lo="−5", bearing=2, hi="+600")
    assert row[words.LIVES_ENGINE_COLUMN] == "+550"


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
    said = sentence(words.METHOD1_RANGE, s="s", bearings=words.listed([2, 3]), scheme="s", films="1.60 / 1.85",
                    critical=fmt.um(1.9e-6, 2)).search(text)
    assert said and "cycle-mean" in said["statistic"]  # the film method 1 reads (life_film)
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
    def capitalised(text):
        return text[0].upper() + text[1:]

    alpha = "alpha_over_limit_pct"
    same = words.SAME_VALUE_PART.format(value=100.0, unit=words.METRIC_UNITS[alpha])
    assert non_discriminating(ranking) == [words.NON_DISCRIMINATING.format(
        metrics=capitalised(words.NON_DISCRIMINATING_NAMES[alpha] + same), verb="does")]
    # a plural name alone takes a plural verb
    ranking = pd.DataFrame({"life_below_target_pct": [0.0, 0.0],
                            "life_below_target_pct_ci": [(0.0, 1.2), (0.0, 1.2)]}, index=["a", "b"])
    assert non_discriminating(ranking) == [words.NON_DISCRIMINATING.format(
        metrics=capitalised(words.NON_DISCRIMINATING_NAMES["life_below_target_pct"] + words.NONE_PART), verb="do")]


def test_positions_where_a_stray_bearing_reaches_the_wall_are_counted_not_described():
    import pandas as pd

    from stackup.facts.mechanics import EdgeContact, FilmOutcomes
    from stackup.report.mechanics import _outcomes_text

    rows = pd.DataFrame({"touching_pct": [0.2, 100.0, 3.0], "cycle_share": [0.02, 0.08, 0.01],
                         "cycle_lo": [0.0, 0.07, 0.0], "cycle_hi": [0.0, 0.11, 0.0], "film": [0.14e-6, 0.11e-6, 0.1e-6],
                         "load": [4.5e3, 2.3e3, 3e3], "angle": [76.0, 122.0, 80.0]}, index=[1, 2, 5])
    edge = EdgeContact(300, 120, [40.0], [0.08], 0.005, per_position=rows)
    text = " ".join(_outcomes_text(FilmOutcomes(300, {}, 0, 180, 120), edge))
    # bearing 2 described; bearings 1 and 5 (under 5 % of the bearings touching) counted after it
    others = words.EDGE_OTHERS_PART.format(count=2, s="s", share="5 %")
    assert edge_sentence(words.EDGE_COUNTED, bearing=2, lo="7.0 %", hi="11 %", positions="", others=others).search(text)
    assert not sentence(words.EDGE_POSITION_PART, bearing=1).search(text)


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
    assert sentence(words.EDGE_COUNTED, edge=32, share="0.3 %", positions=words.EDGE_FEW_PART.format(
        count=2, s="s", share="5 %"), others="").search(text)
    assert ": ;" not in text and not sentence(words.EDGE_POSITION_PART).search(text)


def test_methods_name_the_caveats_of_the_standards_schemes_and_no_anchor_on_its_own_drawing(small_comparison):
    methods = section_text((small_comparison.folder / "report.md").read_text(), "Methods and assumptions")
    fine = words.ISO_NARROW_PART.format(scheme="iso13778-6", parts="housing and journal", width="1.0", of="gauge",
                                        sigma="0.5")  # the example engine's 0.5 um gauge on 1 um classes
    assert words.ISO_CAVEATS.format(items=fine) in methods
    assert "ISO schemes on this drawing" not in methods  # iso-example is the standard's drawing: nothing re-centred
