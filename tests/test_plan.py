"""Grade-quantity planning: conservation, symmetry, service level by simulation, bad input."""

import math

import numpy as np
import pandas as pd
import pytest

from stackup.cli import main
from stackup.plan import optimise_supply, plan, simulate_lot_coverage


@pytest.fixture(scope="module")
def plan4():
    return plan("iso13778-4", volume=10_000, service_level=0.99, sample_engines=20_000)


def test_parts_are_conserved(plan4):
    assert plan4.production_share.sum() + plan4.attrs["scrap_share"] == pytest.approx(1.0, abs=1e-12)
    assert plan4.made.sum() == pytest.approx(plan4.attrs["shells_made"] * (1 - plan4.attrs["scrap_share"]))
    # every paired bearing asks for two shells
    assert plan4.demand_per_1000.sum() == pytest.approx(2 * 5 * 1000, rel=0.002)


def test_symmetric_processes_give_symmetric_demand(plan4):
    d = plan4.demand_per_1000
    half = 0.5 * (plan4.demand_per_1000_hi - plan4.demand_per_1000_lo)
    assert abs(d["A"] - d["E"]) < 2 * np.hypot(half["A"], half["E"])
    assert abs(d["B"] - d["D"]) < 2 * np.hypot(half["B"], half["D"])


def test_safety_stock_meets_the_service_level_in_simulation(plan4):
    lots = 400
    coverage = simulate_lot_coverage("iso13778-4", order_up_to=plan4.order_up_to.to_numpy(),
                                     lot_engines=plan4.attrs["lot_engines"], lots=lots, seed=3)
    tolerance = 3 * np.sqrt(0.99 * 0.01 / lots)
    assert np.all(coverage >= 0.99 - tolerance)


def test_more_service_needs_more_stock():
    low = plan("iso13778-5", volume=1000, service_level=0.9, sample_engines=5000)
    high = plan("iso13778-5", volume=1000, service_level=0.999, sample_engines=5000)
    assert np.all(high.safety_stock >= low.safety_stock) and (high.safety_stock > low.safety_stock).any()


@pytest.mark.parametrize("kw, message", [
    (dict(volume=0), "volume: 0 is not valid; must be >= 1"),
    (dict(volume=100, service_level=1.0), r"service_level: 1.0 is outside the valid range \(0.0, 1.0\)"),
    (dict(volume=100, service_level=0.0), r"service_level: 0.0 is outside the valid range \(0.0, 1.0\)"),
])
def test_bad_input(kw, message):
    with pytest.raises(ValueError, match=message):
        plan("iso13778-5", **kw)


def test_unknown_scheme():
    with pytest.raises(ValueError, match="scheme: 'iso13778-8' is not a known scheme"):
        plan("iso13778-8", volume=100)


def test_cli_plan(capsys):
    assert main(["plan", "--scheme", "iso13778-5", "--volume", "2000", "--sample", "2000"]) == 0
    out = capsys.readouterr().out
    assert "safety" in out and "[shells]" in out and "\nB " in out
    assert main(["plan", "--scheme", "iso13778-5", "--volume", "-5"]) == 2
    assert "argument --volume: -5 engines is too few; give at least 1" in capsys.readouterr().err


def test_optimiser_matches_brute_force_on_a_small_case():
    from stackup.plan import allocate, optimise_supply
    from stackup.schemes import load

    scheme = load("iso13778-2")  # one preferred pair, B+B, with the alternative A+C
    r = optimise_supply(scheme, volume=12, sample_engines=2000, shortage_cost=10.0)
    demand_bb = r["demand"][scheme.shell.labels.index("B") * 4]
    lo, hi = scheme.shell.limits
    best = np.inf
    for mean in np.linspace(lo, hi, 801):
        s = r["supply"](mean)
        a, b, c = s  # supply of A, B, C
        for k in np.linspace(0, demand_bb, 241):  # bearings served by A+C instead of B+B
            use = np.array([k, 2 * (demand_bb - k), k])
            surplus = np.maximum(s - use, 0)
            short = np.maximum(use - s, 0)
            best = min(best, surplus.sum() + 10.0 * short.sum())
    assert r["objective"] <= best + 1e-6 * max(best, 1)
    assert best <= r["objective"] + 0.01 * max(r["objective"], 1)  # the grid comes close to the optimiser
    # the LP on its own agrees with the brute force at the optimiser's mean
    value, *_ = allocate(scheme, r["demand"], r["supply"](r["mean"]))
    assert value == pytest.approx(r["objective"])


def test_optimised_mean_beats_the_centred_process_when_demand_is_off_centre():
    from stackup.engines import load_engine
    from stackup.plan import optimise_supply
    from stackup.scenarios import apply

    shifted = apply(load_engine("iso-example"), {"journal_shift": 1.5})  # larger journals: thinner shells needed
    r = optimise_supply("iso13778-5", shifted, volume=5000, sample_engines=5000)
    assert r["objective"] < r["centred_objective"]
    lo, hi = 1.972e-3, 1.990e-3
    assert r["mean"] < 0.5 * (lo + hi)


def test_housing_and_journal_grades_where_the_scheme_grades_them():
    h = plan("iso13778-4", volume=1000, part="housing", sample_engines=5000)
    j = plan("iso13778-4", volume=1000, part="journal", sample_engines=5000)
    for frame in (h, j):
        assert list(frame.index) == ["A", "B", "C"]
        assert frame.share.sum() + frame.attrs["ungradable_share"] == pytest.approx(1.0)
        assert frame.share["B"] > frame.share["A"]  # centred processes: the middle grade is the most common
        assert abs(frame.per_1000["A"] - frame.per_1000["C"]) < 2 * (frame.per_1000_hi["A"] - frame.per_1000_lo["A"])
    with pytest.raises(ValueError, match="part: scheme iso13778-3 does not grade the housing"):
        plan("iso13778-3", volume=10, part="housing", sample_engines=500)


def test_plan_from_a_study_dataset_agrees_with_the_process_plan():
    import stackup

    ds = stackup.Study(n_engines=8000, schemes=("iso13778-4", "iso13778-5"), mechanics_engines=0, pilot_engines=20_000,
                       progress=False).run()
    from_ds = stackup.plan(ds, volume=10_000)
    assert list(from_ds.index.get_level_values("scheme").unique()) == ["iso13778-4", "iso13778-5"]
    direct = plan("iso13778-5", volume=10_000, sample_engines=20_000)
    for g in ("A", "B", "C"):
        lo, hi = from_ds.loc[("iso13778-5", g), ["demand_per_1000_lo", "demand_per_1000_hi"]]
        assert lo - 30 <= direct.demand_per_1000[g] <= hi + 30  # two independent samples of the same demand
    from stackup.plan import planner_table

    table = planner_table(from_ds)
    for scheme in ("iso13778-4", "iso13778-5"):
        rows = table.xs(scheme, level="scheme")
        for column in ("needed, 10000 engines [shells]", "made, 10000 engines [shells]"):
            assert rows.loc["all shells", column] == rows.drop("all shells")[column].sum()
        # the shells made add up to what the title says, scrap included
        assert rows.loc["all shells", "made, 10000 engines [shells]"] == from_ds.attrs["shells_made"] == 110_000
    title = " ".join(table.attrs["title"])
    assert "from the 8,000 engines of the study dataset" in title
    assert "Scheme iso13778-4: of the 110,000 shells made for the volume" in title


@pytest.mark.parametrize("p, lot", [(0.3, 1), (0.088, 7), (0.5, 50), (0.9, 1000)])
def test_lot_demand_quantile_is_the_binomial_quantile_for_one_part_at_most_per_engine(p, lot):
    # each engine asks for one part with probability p: the lot's demand is Binomial(lot, p) (closed form)
    from scipy import stats

    from stackup.plan import lot_demand_quantile

    n = 1000
    sample = np.r_[np.ones(round(p * n), dtype=int), np.zeros(n - round(p * n), dtype=int)]
    for level in (0.9, 0.99, 0.999):
        assert lot_demand_quantile(sample, lot, level) == stats.binom.ppf(level, lot, round(p * n) / n)


def test_lot_demand_quantile_of_huge_lots_falls_back_to_the_normal_approximation():
    from scipy import stats

    from stackup.plan import EXACT_LOT_SUPPORT, lot_demand_quantile

    lot = EXACT_LOT_SUPPORT  # support past the exact limit
    sample = np.r_[np.ones(300, dtype=int), np.zeros(700, dtype=int)]
    exact = stats.binom.ppf(0.99, lot, 0.3)
    assert abs(lot_demand_quantile(sample, lot, 0.99) - exact) <= 0.001 * np.sqrt(lot * 0.21) + 1


def test_stock_for_a_small_lot_meets_the_service_level_in_simulation():
    # the normal approximation covers 98.4 % of lots of 50 engines with scheme 4; the exact quantile covers 99 %
    small = plan("iso13778-4", volume=50, service_level=0.99, sample_engines=20_000)
    assert small.attrs["lot_engines"] == 50 and "one lot of 50 engines" in small.attrs["lot_note"]
    lots = 2000
    coverage = simulate_lot_coverage("iso13778-4", order_up_to=small.order_up_to.to_numpy(), lot_engines=50,
                                     lots=lots, seed=11)
    assert np.all(coverage >= 0.99 - 3 * np.sqrt(0.99 * 0.01 / lots))


def test_lots_and_volumes_that_contradict_each_other():
    with pytest.raises(ValueError, match="lot_engines: a lot of 20,000 engines is more than the volume of 10,000"):
        plan("iso13778-5", volume=10_000, lot_engines=20_000, sample_engines=500)
    seven = plan("iso13778-5", volume=7, sample_engines=500)
    assert seven.attrs["lot_engines"] == 7 and seven.attrs["shells_made"] == math.ceil(7 * 5 * 2 * 1.1)
    whole = plan("iso13778-5", volume=2500, lot_engines=1000, sample_engines=500)
    assert whole.attrs["lot_note"] == ""
    for name, value in (("lot_engines", 10), ("service_level", 0.95)):
        with pytest.raises(ValueError, match=f"{name}: applies to the shell stock only; journals are graded"):
            plan("iso13778-4", volume=100, part="journal", sample_engines=500, **{name: value})


def test_planner_table_is_whole_parts_that_add_up(plan4):
    from stackup.plan import planner_table

    table = planner_table(plan4)
    grades = table.drop(["scrapped", "all shells"])
    made = table["made, 10000 engines [shells]"]
    # apportioned: the grades and the scrap add up to the shells made, which the title states
    assert made.drop("all shells").sum() == made["all shells"] == plan4.attrs["shells_made"] == 110_000
    assert (abs(made.drop(["scrapped", "all shells"]) - plan4.made) < 1).all()
    assert abs(made["scrapped"] - plan4.attrs["scrap_share"] * 110_000) < 1
    assert f"Of the 110,000 shells made for the volume the gauge sorts {110_000 - made['scrapped']:,} into the grades" \
        in " ".join(table.attrs["title"])
    assert (grades["needed, 10000 engines [shells]"] >= plan4.demanded - 1e-6).all()  # a whole number stays one
    assert (grades["stock per lot of 1000 engines [shells]"] >= plan4.lot_demand_mean).all()
    assert table.loc["all shells", "stock per lot of 1000 engines [shells]"] == plan4.order_up_to.sum()
    ordered = table["ordered per lot of 1000 engines, aimed at the grade [shells]"]
    assert ordered["all shells"] == ordered.drop("all shells").sum() == plan4.attrs["shells_per_lot"] == 11_000
    assert table.attrs["title"][0].startswith("How many shells of each grade to make and stock for 10,000 engines")


def test_old_processes_keyword_still_works_with_a_deprecation_warning():
    new = plan("iso13778-5", engine="iso-example", volume=1000, sample_engines=500)
    with pytest.warns(DeprecationWarning, match="processes= is deprecated; use engine="):
        old = plan("iso13778-5", processes="iso-example", volume=1000, sample_engines=500)
    pd.testing.assert_frame_equal(old, new)
    with pytest.warns(DeprecationWarning, match="processes= is deprecated"):
        supply = optimise_supply("iso13778-5", processes="iso-example", volume=50, sample_engines=500)
    assert supply["mean"] == optimise_supply("iso13778-5", engine="iso-example", volume=50, sample_engines=500)["mean"]
    with pytest.warns(DeprecationWarning, match="processes= is deprecated"):
        covered = simulate_lot_coverage("iso13778-5", processes="iso-example", order_up_to=[99] * 3, lot_engines=5,
                                        lots=3)
    assert np.all(covered == 1.0)
    with pytest.raises(TypeError, match="not both"):
        plan("iso13778-5", engine="iso-example", processes="iso-example", volume=10)


def test_unasked_shells_are_counted_with_the_alternative_pairs_that_could_fit_them():
    """Hand-counted: which grades no preferred pair asks for, and how many of their shells the alternatives take."""
    from stackup.plan import unasked
    from stackup.schemes import load

    # ISO scheme 2: B+B preferred, A+C allowed; both A and C unasked. 1000 B+B bearings want 2000 B shells.
    frame = pd.DataFrame({"made": [300.0, 2100.0, 500.0], "demanded": [0.0, 2000.0, 0.0]},
                         index=pd.Index(["A", "B", "C"], name="grade"))
    record = unasked(load("iso13778-2"), frame)
    assert record["grades"] == ["A", "C"] and record["shells"] == 800 and record["share"] == 800 / 2900
    assert record["alternatives"] == ["A+C for B+B"]
    assert record["pairs"] == 300 and record["used"] == 600  # A runs out first; each pair takes an A and a C
    # ISO scheme 6: only D unasked; B+C may take A+D, C+C may take B+D: each such pair takes one D
    frame = pd.DataFrame({"made": [100.0, 900.0, 1000.0, 50.0], "demanded": [80.0, 800.0, 900.0, 0.0]},
                         index=pd.Index(list("ABCD"), name="grade"))
    record = unasked(load("iso13778-6"), frame)
    assert record["grades"] == ["D"] and record["alternatives"] == ["A+D for B+C", "B+D for C+C"]
    # A+D: min(bearings wanted 800, spare A 20, spare D 50) = 20; B+D: min(900 / 2, spare B 100, spare D 30) = 30
    assert record["pairs"] == 50 and record["used"] == 50
    # nothing unasked: an empty record (no line in the table's title)
    assert unasked(load("iso13778-2"), pd.DataFrame({"made": [1.0, 10.0, 1.0], "demanded": [1.0, 9.0, 1.0]},
                                                     index=pd.Index(list("ABC")))) == {}


def test_the_title_names_grades_whose_order_falls_short_of_their_stock(plan4):
    """A grade whose shells made per lot (the made column over the 10 lots) are below its stock per lot is named."""
    from stackup.plan import planner_table

    table = planner_table(plan4)
    grades = table.drop(["scrapped", "all shells"])
    per_lot = grades["made, 10000 engines [shells]"] / 10
    stock = grades["stock per lot of 1000 engines [shells]"]
    short = [g for g in grades.index if per_lot[g] < stock[g] - 0.5]
    line = next((line for line in table.attrs["title"] if line.startswith("The order falls short")), "")
    assert short and set(short) < set(grades.index)  # the thin edge grades, not the middle ones
    for g in grades.index:
        assert (f" {g} (" in line) == (g in short), g
    frame = plan4.copy()
    frame.attrs = dict(plan4.attrs)
    middle = frame.order_up_to.idxmax()
    frame.loc[middle, "made"] = 10 * frame.loc[middle, "order_up_to"] - 50
    line = next(line for line in planner_table(frame).attrs["title"] if line.startswith("The order falls short"))
    assert f" {middle} (" in line and f"against {int(frame.loc[middle, 'order_up_to']):,})" in line


@pytest.mark.integration
def test_the_table_of_one_scheme_of_a_study_speaks_of_that_scheme_only():
    """The report plans the scheme it recommends: a frame cut to it carries no other scheme's lines."""
    from stackup.plan import planner_table
    from stackup.study import Study

    ds = Study(schemes=["iso13778-2", "iso13778-4"], n_engines=300, seed=2).run()
    frame = plan(ds, volume=1000)
    one = frame.loc[["iso13778-4"]]
    one.attrs = dict(frame.attrs)
    title = " ".join(planner_table(one).attrs["title"])
    assert "iso13778-2" not in title.split("?", 1)[1]  # past the heading's question
    assert "Scheme iso13778-2" in " ".join(planner_table(frame).attrs["title"])  # A and C of scheme 2, unasked


def test_an_iso_scheme_by_name_is_planned_on_the_engines_drawing_as_a_comparison_lays_it(capsys):
    from stackup.engines import load_engine
    from stackup.patterns import laid_on
    from stackup.schemes import scheme_path
    from stackup.study.inputs import scheme_text

    engine = load_engine("nef-6")
    laid = laid_on("iso13778-5", engine)
    assert scheme_text("iso13778-5", engine) == laid.to_toml_text()  # the study's scheme is this one
    by_name = plan("iso13778-5", engine, volume=1000, sample_engines=500)
    pd.testing.assert_frame_equal(by_name, plan(laid, engine, volume=1000, sample_engines=500), check_like=True)
    assert by_name.demand_per_1000.sum() == pytest.approx(2 * 7 * 1000, rel=0.002)
    assert by_name.attrs["laid_on"] == "nef-6"
    with pytest.raises(ValueError, match="no bearing of the pilot sample could be graded"):
        plan(scheme_path("iso13778-5"), engine, volume=1000, sample_engines=500)  # a file is the user's drawing
    assert main(["plan", "--scheme", "iso13778-5", "--engine", "nef-6", "--volume", "1000", "--sample", "500"]) == 0
    assert "iso13778-5 is ISO 13778's pattern laid on nef-6's drawing" in capsys.readouterr().out
