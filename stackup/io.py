"""Saving and opening study datasets (netCDF-4 or Zarr by the path's suffix), so a saved file reproduces itself."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from .study.store import open_study, to_stored


def save(ds, path):
    """Write ``ds`` to ``path``: a Zarr store if it ends in ``.zarr``, else netCDF-4 (compressed).

    netCDF keeps strings as character arrays; Zarr keeps grade labels as int8
    codes with their labels (:func:`stackup.study.store.to_stored`).
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    if path.suffix == ".zarr":
        labels = {str(v) for var in ds.data_vars.values() if var.dtype.kind == "U" for v in np.unique(var.values)}
        to_stored(ds, labels).to_zarr(path, mode="w-", consolidated=False, zarr_format=3)
        return path
    encoding = {}
    for name, var in ds.variables.items():
        if var.dtype.kind == "U":
            encoding[name] = {"dtype": "S1", "zlib": True}
        elif var.dtype.kind in "fiub" and var.ndim > 0 and name not in ds.dims:
            encoding[name] = {"zlib": True, "complevel": 1}
    ds.to_netcdf(path, encoding=encoding, engine="netcdf4")
    return path


def open_dataset(path):
    """Load a saved study dataset (netCDF-4 or Zarr) into memory, strings back as numpy unicode."""
    path = Path(path)
    if path.suffix == ".zarr":
        return open_study(path).load()
    ds = xr.load_dataset(path, engine="netcdf4")
    for name, var in ds.variables.items():
        if var.dtype == object:
            ds[name] = var.astype(str)
    return ds
