"""Issue 30: the main job's dataset is identical before and after the re-layering (temporary: the dataset saved
before the change is not in the repository; this test is deleted with it once the change has landed)."""

import json
import os
from pathlib import Path

import pytest
import xarray as xr

from stackup.io import open_comparison

BEFORE = Path(os.environ.get("STACKUP_BEFORE", "/work/baseline/compare/compare.nc"))
AFTER = Path(os.environ.get("STACKUP_AFTER", "/work/after/compare/compare.nc"))
#: Attributes that hold the package version or a wall time, not results.
VOLATILE = ("stackup_version",)


def _stable(ds):
    ds = ds.copy()
    ds.attrs = {k: v for k, v in ds.attrs.items() if k not in VOLATILE}
    if "design" in ds.attrs:
        record = json.loads(ds.attrs["design"])
        record.pop("seconds")
        record["notes"] = [n for n in record["notes"] if not n.startswith("Design time")]
        ds.attrs["design"] = json.dumps(record)
    if "input_files" in ds.attrs:
        files = json.loads(ds.attrs["input_files"])
        files["schemes"] = {k: "\n".join(line for line in v.splitlines() if "Design time" not in line)
                            for k, v in files["schemes"].items()}
        ds.attrs["input_files"] = json.dumps(files)
    return ds


@pytest.mark.skipif(not (BEFORE.exists() and AFTER.exists()), reason="the saved main-job datasets are not here")
def test_main_job_dataset_identical_before_and_after_the_relayering():
    before, after = open_comparison(BEFORE), open_comparison(AFTER)
    xr.testing.assert_identical(_stable(before.dataset), _stable(after.dataset))
    xr.testing.assert_identical(_stable(before.tails), _stable(after.tails))
    xr.testing.assert_identical(_stable(before.sensitivity), _stable(after.sensitivity))
    assert list(before.scenarios) == list(after.scenarios)
    for label in before.scenarios:
        xr.testing.assert_identical(_stable(before.scenarios[label]), _stable(after.scenarios[label]))
