"""The verdict's first paragraph puts each figure beside its own scheme, and the first page names bearings below the
minimum clearance at assembly or cold start and a window that does not suit the housing (issue 51, items 2 and 5).

Made-up rankings (:func:`stackup.rank.ranked` of :class:`stackup.facts.RankingRows`) and the few facts the verdict
reads, so each case is a unit test; the built-in aluminium engine's whole comparison is
``tests/test_comparison_cold_start.py``.
"""

import re
from types import SimpleNamespace

import numpy as np
import pytest

from stackup.facts import RankingRows
from stackup.rank import ranked
from stackup.report import templates as words
from stackup.report.verdict import (
    _use,
    decision_table,
    interference,
    window_at_cold_start,
)

WINDOW = (34.5e-6, 57.5e-6)


def _ranking(**schemes):
    """Ranked made-up schemes: name -> (share outside the window [ppm], its interval, operating clearance mean [um],
    bearings below the minimum clearance of 2000, cold-start clearance mean [um])."""
    rows = {}
    for name, (share, ci, mean, below, cold) in schemes.items():
        below_ppm = 1e6 * below / 2000
        rows[name] = {"outside_window_ppm": share, "outside_window_ppm_ci": ci, "outside_window_source": "counted",
                      "shell_grades": 3, "part_grades": 6, "stockout_ppm": 0.0, "stockout_ppm_ci": (0.0, 1.0),
                      "surplus_pct": 9.0, "clearance_mean_um": mean, "clearance_std_um": 1.8,
                      "below_minimum_ppm": below_ppm,
                      "below_minimum_ppm_ci": (max(0.0, 0.7 * below_ppm), 1.3 * below_ppm + 1500.0),
                      "below_minimum_counted": below, "clearance_assembly_mean_um": cold + 17.0,
                      "clearance_assembly_std_um": 1.8, "clearance_cold_mean_um": cold, "clearance_cold_std_um": 1.8}
    return ranked(RankingRows(rows, {}, WINDOW, {}))


FACTS = SimpleNamespace(limits=SimpleNamespace(minimum_clearance=1e-6, cold_start_temperature=-30.0),
                        press_fit=SimpleNamespace(housing_material="aluminium", assembly_temperature=20.0))


def test_each_operating_clearance_in_the_verdict_stands_beside_its_own_scheme():
    # the case: the recommended scheme at 54.6 um, iso13778-1 at 103.7 um and wholly outside the window; the
    # old wording put 54.6 um after iso13778-1's name
    ranking = _ranking(designed=(0.5, (0.1, 0.9), 54.6, 0, 20.0), **{"iso13778-1": (1e6, (999_000.0, 1e6), 103.7,
                                                                                      0, 69.0)})
    text = _use(FACTS, ranking, WINDOW)
    beside = dict(re.findall(r"\**([\w-]+)\** \(operating clearance ([\d.]+) ± [\d.]+ µm\)", text))
    assert beside == {"designed": "54.6", "iso13778-1": "103.7"}, text


def test_a_scheme_with_fewer_bearings_below_the_minimum_clearance_ranks_first_and_the_verdict_says_why():
    ranking = _ranking(tight=(0.5, (0.1, 0.9), 46.0, 880, 1.2), loose=(1e6, (999_000.0, 1e6), 87.0, 0, 47.0))
    assert list(ranking.index) == ["loose", "tight"]
    text = _use(FACTS, ranking, WINDOW)
    assert text.startswith("**Use loose** (operating clearance 87.0") and "for tight (operating clearance 46.0" in text
    assert "0 ppm [0, 1,500] of its bearings below the minimum clearance at assembly or cold start against 440,000 ppm" \
        in text
    paragraph = interference(FACTS, ranking)
    assert paragraph.startswith("**Interference:** 44 % of tight's bearings (cold: 1.2 ± 1.8 µm) below the 1 µm")
    assert "−30 °C; loose none." in paragraph
    table = decision_table(SimpleNamespace(scenario_about={}, ranking=None), ranking)
    assert list(table[words.BELOW_MINIMUM_COLUMN]) == ["0", "440000 [308000, 573500]"]


def test_the_recommended_scheme_below_the_minimum_is_named_when_every_scheme_is():
    ranking = _ranking(a=(0.5, (0.1, 0.9), 46.0, 30, 6.0), b=(1e6, (999_000.0, 1e6), 30.0, 1900, -10.0))
    assert ranking.index[0] == "a"
    paragraph = interference(FACTS, ranking)
    assert "1.5 % of a's bearings (cold: 6.0 ± 1.8 µm) and 95 % of b's bearings (cold: −10.0 ± 1.8 µm)" in paragraph
    assert paragraph.endswith("no scheme compared has fewer than a.")


def test_no_scheme_below_the_minimum_and_a_window_that_suits_the_housing_say_nothing():
    # an iron housing: the clearance opens a little from operating to cold, every bearing well above the minimum
    ranking = _ranking(a=(22.0, (18.0, 27.0), 44.9, 0, 52.0), b=(68_500.0, (57_818.0, 80_466.0), 38.0, 0, 45.0))
    assert interference(FACTS, ranking) is None
    assert window_at_cold_start(FACTS, ranking, WINDOW) is None


@pytest.mark.parametrize("lower_edge_cold, named", [(-5.3, True), (0.9, True), (1.1, False)])
def test_a_window_whose_lower_edge_falls_below_the_minimum_at_the_cold_start_is_named(lower_edge_cold, named):
    # the recommended scheme's clearance falls by (operating - cold) from service to the cold start
    cold = 46.0 - (34.5 - lower_edge_cold)
    ranking = _ranking(a=(0.5, (0.1, 0.9), 46.0, 0, cold))
    text = window_at_cold_start(FACTS, ranking, WINDOW)
    assert (text is not None) == named
    if named:
        lo = f"{lower_edge_cold:.1f}".replace("-", "−")
        assert text.startswith(f"**Window:** 34.5–57.5 µm in service is {lo}–") and "aluminium housing" in text


def test_a_ranking_without_the_cold_start_counts_reads_as_before():
    # a dataset saved before the counts: no column, so the rule goes on to the window and nothing is said
    rows = {name: {"outside_window_ppm": share, "outside_window_ppm_ci": (share, share),
                   "outside_window_source": "counted", "shell_grades": 3, "part_grades": 6, "stockout_ppm": 0.0,
                   "stockout_ppm_ci": (0.0, 1.0), "surplus_pct": 9.0, "clearance_mean_um": 45.0,
                   "clearance_std_um": 2.0} for name, share in (("a", 5.0), ("b", 500.0))}
    ranking = ranked(RankingRows(rows, {}, WINDOW, {}))
    assert list(ranking.index) == ["a", "b"] and "below_minimum_ppm" not in ranking
    assert interference(FACTS, ranking) is None and window_at_cold_start(FACTS, ranking, WINDOW) is None
    assert not np.isnan(ranking.loc["a", "clearance_mean_um"])


def test_no_centring_advice_for_a_scheme_whose_bearings_fall_below_the_minimum_clearance_cold():
    import pandas as pd

    from stackup.report.sections import centring

    ranking = _ranking(tight=(0.5, (0.1, 0.9), 44.6, 140, 5.1), loose=(1e6, (999_000.0, 1e6), 93.8, 0, 54.0))
    ranking.loc["tight", "clearance_std_um"] = 1.0  # the narrowest, below the window's middle
    facts = SimpleNamespace(centred=pd.DataFrame({"shift": [1.4e-6], "outside": [0], "bearings": [2000]},
                                                 index=["tight"]))
    assert ranking.index[0] == "loose" and centring(facts, ranking) == []
    # the same scheme without bearings below the minimum would be the chosen one: nothing to centre either way, so
    # the advice is tested where the narrowest is the runner on the window alone
    level = _ranking(tight=(900.0, (800.0, 1000.0), 44.6, 0, 5.1), wide=(0.5, (0.1, 0.9), 46.0, 0, 6.0))
    level.loc["tight", "clearance_std_um"] = 1.0
    advice = centring(facts, level)
    assert advice and advice[0].startswith("**Centring:** tight has the narrowest operating clearance")


def test_a_few_bearings_below_the_minimum_are_counted_in_ppm_not_rounded_to_zero_per_cent():
    ranking = _ranking(a=(0.5, (0.1, 0.9), 46.0, 0, 20.0), b=(1e6, (999_000.0, 1e6), 46.0, 1, 9.0))
    assert "500 ppm of b's bearings" in interference(FACTS, ranking)
