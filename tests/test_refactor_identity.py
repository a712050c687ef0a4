"""Issue 14: the study layer's redesign changes no result (datasets saved by the code before it)."""

from pathlib import Path

import pytest
import xarray as xr

from stackup.io import open_dataset, save
from stackup.study import Study

DATA = Path(__file__).parent / "data"
CASES = {
    "full": dict(n_engines=600, seed=3, mechanics_engines=12, history=True, crank_angle_step=6.0, pilot_engines=3000),
    "summaries": dict(n_engines=3000, seed=3, mechanics_engines=30, keep="summaries", crank_angle_step=6.0,
                      pilot_engines=3000),
    "qmc_scenario": dict(n_engines=1500, seed=5, mechanics_engines=10, sampler="qmc", scenario={"housing_shift": 1.0},
                         schemes=("iso13778-4", "iso13778-6"), film_method="auto", crank_angle_step=6.0,
                         pilot_engines=3000),
    "target": dict(n_engines=2000, seed=7, mechanics_engines=100, target_error=0.2, schemes=("iso13778-2",),
                   crank_method="linear", fit_method="thin-ring", crank_angle_step=6.0, pilot_engines=3000),
}
#: The summaries now take the shell counters' long names from the one schema the full dataset uses.
RENAMED = {"shells_used": "shells of the grade fitted to bearings",
           "shells_left": "shells of the grade left in stock at the ends of the lots",
           "shells_scrapped": "shells read outside every grade of the scheme (scrapped)"}


@pytest.mark.parametrize("case", CASES)
def test_same_seed_gives_the_dataset_saved_before_the_redesign(case, tmp_path):
    before = open_dataset(DATA / f"before_refactor_{case}.nc")
    if case == "summaries":
        for name, long_name in RENAMED.items():
            before[name].attrs["long_name"] = long_name
    after = open_dataset(save(Study(progress=False, **CASES[case]).run(), tmp_path / "after.nc"))
    added = set(after.attrs) - set(before.attrs)  # attributes are only added: the reports read them
    assert added <= {"contact_pressure_min", "shell_stress_max", "engine_source", "lot_engines", "shell_surplus",
                     "shell_supply", "pilot_engines", "scheme_sources", "press_fit", "life_target",
                     "crush_height_limits"}
    if case == "summaries":  # the summaries now carry the schemes' clearance ranges as the full dataset does
        assert set(after.data_vars) - set(before.data_vars) == {"clearance_stated", "clearance_limit"}
        after = after.drop_vars(["clearance_stated", "clearance_limit", "bound"])
    xr.testing.assert_identical(after.drop_attrs(deep=False).assign_attrs({k: after.attrs[k] for k in before.attrs}),
                                before)
