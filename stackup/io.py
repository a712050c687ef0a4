"""Saving and opening study datasets (netCDF-4), so a saved file reproduces itself."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr


def save(ds, path):
    """Write ``ds`` to netCDF-4 at ``path`` (compressed; strings as character arrays)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    encoding = {}
    for name, var in ds.variables.items():
        if var.dtype.kind == "U":
            encoding[name] = {"dtype": "S1", "zlib": True}
        elif var.dtype.kind in "fiub" and var.ndim > 0 and name not in ds.dims:
            encoding[name] = {"zlib": True, "complevel": 1}
    ds.to_netcdf(path, encoding=encoding, engine="netcdf4")
    return path


def open_dataset(path):
    """Load a saved study dataset into memory, strings back as numpy unicode."""
    ds = xr.load_dataset(path, engine="netcdf4")
    for name, var in ds.variables.items():
        if var.dtype == object:
            ds[name] = var.astype(str)
    return ds
