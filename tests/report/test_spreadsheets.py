"""The report's tables as CSV (``stackup report --csv``): the numbers of the facts, units in the column names."""

import numpy as np
import pandas as pd

from stackup.cli import main
from stackup.facts import facts
from stackup.output import RUN_FILES
from stackup.rank import ranked
from stackup.report.spreadsheets import FILES, numbers


def test_intervals_and_triples_become_columns_with_their_units():
    frame = pd.DataFrame({"outside_window_ppm": [12.0, 3.0], "outside_window_ppm_ci": [(10.0, 14.0), None],
                          "h_min_p05_um": [(0.4, 0.3, 0.5), (0.6, 0.5, 0.7)], "shell_grades": [3, 5],
                          "outside_window_source": ["counted", "shells integrated out"]},
                         index=pd.Index(["a", "b"], name="scheme"))
    table = numbers(frame)
    assert list(table.columns) == ["outside_window [ppm]", "outside_window 95 % low [ppm]",
                                   "outside_window 95 % high [ppm]", "h_min_p05 [um]", "h_min_p05 95 % low [um]",
                                   "h_min_p05 95 % high [um]", "shell_grades [grades]", "outside_window_source"]
    assert table.loc["a", "outside_window 95 % high [ppm]"] == 14.0
    assert np.isnan(table.loc["b", "outside_window 95 % low [ppm]"])  # no interval: empty, not made up
    assert table.loc["b", "h_min_p05 95 % low [um]"] == 0.5


def test_report_csv_writes_the_ranking_and_the_film_and_life_tables_of_the_saved_comparison(small_comparison,
                                                                                              tmp_path, capsys):
    saved, dataset = small_comparison.comparison, str(small_comparison.folder / "compare.nc")
    assert main(["report", dataset, "--out", str(tmp_path), "--csv"]) == 0
    assert "ranking.csv" in capsys.readouterr().out
    known = facts(saved.dataset, scenarios=saved.scenarios, sensitivity=saved.sensitivity, tails=saved.tails)
    expected = ranked(known.ranking)  # what stackup.rank(saved) returns
    ranking = pd.read_csv(tmp_path / "ranking.csv", index_col="scheme")
    assert list(ranking.index) == list(expected.index) and list(ranking["rank [-]"]) == list(expected["rank"])
    np.testing.assert_allclose(ranking["outside_window [ppm]"], expected.outside_window_ppm)
    np.testing.assert_allclose(ranking["outside_window 95 % high [ppm]"],
                               [ci[1] for ci in expected.outside_window_ppm_ci])
    film = pd.read_csv(tmp_path / "film_life.csv", index_col="scheme")
    assert list(film.index) == list(expected.index)
    np.testing.assert_allclose(film["engine_life_median [h]"],
                               [known.film.engine_life_median_h[s][0] for s in film.index])
    positions = pd.read_csv(tmp_path / "film_life_per_bearing.csv", index_col=["scheme", "bearing"])
    assert len(positions) == len(expected) * saved.dataset.sizes["bearing"]
    assert positions["load_cycle_max_mean [kN]"].gt(0).all() and "life_median 95 % low [h]" in positions
    # report files: a report written again replaces them, so no table outlives its report
    assert set(FILES) <= {p.name for pattern in RUN_FILES for p in tmp_path.glob(pattern)}
