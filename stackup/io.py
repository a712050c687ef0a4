"""Saving and opening study datasets (netCDF-4 or Zarr by the path's suffix), so a saved file reproduces itself.

A comparison (:class:`stackup.comparison.Comparison`) is one file: the
study in the root group, each scenario's summaries in a group
``scenario_<k>`` (its label in the attribute ``scenario``), the
sensitivity dataset in the group ``sensitivity`` and the tail estimates in
the group ``tails``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from ._comparison import Comparison
from .study.schema import STORED_RESOLUTION, STORED_RESOLUTION_OF
from .study.store import open_study, to_stored


def save(ds, path, *, group=None, compact=False):
    """Write ``ds`` to ``path``: a Zarr store if it ends in ``.zarr``, else netCDF-4 (compressed).

    netCDF keeps strings as character arrays; Zarr keeps grade labels as int8
    codes with their labels (:func:`stackup.study.store.to_stored`). With
    ``group`` the dataset is added to an existing file as that group.

    ``compact`` stores the per-bearing values (two dimensions or more) to the
    resolution of :data:`stackup.study.schema.STORED_RESOLUTION` by their
    units (:data:`~stackup.study.schema.STORED_RESOLUTION_OF` by name), as CF packed integers (``scale_factor``, ``add_offset``; NaN as
    ``_FillValue``), and other floating-point values of that size as float32,
    with byte shuffling before compression: a much smaller file, and every
    value within half the resolution of what was computed.
    """
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    mode = "w" if group is None else "a"
    if path.suffix == ".zarr":
        labels = {str(v) for var in ds.data_vars.values() if var.dtype.kind == "U" for v in np.unique(var.values)}
        to_stored(ds, labels).to_zarr(path, mode="w-" if group is None else "a", group=group, consolidated=False,
                                      zarr_format=3)
        return path
    encoding = {}
    for name, var in ds.variables.items():
        if var.dtype.kind == "U":
            encoding[name] = {"dtype": "S1", "zlib": True, **({"shuffle": True} if compact else {})}
        elif var.dtype.kind in "fiub" and var.ndim > 0 and name not in ds.dims:
            encoding[name] = {"zlib": True, "complevel": 1, "shuffle": True}
            if compact and var.ndim >= 2:
                encoding[name].update(shuffle=True, **_packing(name, var))
    ds.to_netcdf(path, mode=mode, group=group, encoding=encoding, engine="netcdf4")
    return path


def _packing(name, var):
    """CF packing of a variable to the stored resolution of its units, or float32 (see :func:`save`)."""
    if var.dtype.kind != "f":
        return {}
    resolution = STORED_RESOLUTION_OF.get(name, STORED_RESOLUTION.get(var.attrs.get("units")))
    values = var.values[np.isfinite(var.values)]
    if resolution is None or values.size == 0:
        return {"dtype": "f4"}
    lo, hi = float(values.min()), float(values.max())
    for dtype in ("i2", "i4"):
        info = np.iinfo(dtype)
        if (hi - lo) / resolution < info.max - info.min - 2:  # the lowest code is the fill value
            return {"dtype": dtype, "scale_factor": resolution, "add_offset": round(0.5 * (lo + hi) / resolution) * resolution,
                    "_FillValue": info.min}
    return {"dtype": "f8"}


def open_dataset(path, *, group=None):
    """Load a saved study dataset (netCDF-4 or Zarr) into memory, strings back as numpy unicode."""
    path = Path(path)
    if path.suffix == ".zarr":
        return open_study(path, group=group).load()
    ds = xr.load_dataset(path, engine="netcdf4", group=group)
    for name, var in ds.variables.items():
        if var.dtype == object:
            ds[name] = var.astype(str)
    return ds


def save_comparison(comparison, path, *, compact=False):
    """Write a :class:`~stackup.comparison.Comparison` into one file (see the module docstring).

    Every value is kept exactly as computed, so ``Study.from_dataset(ds).run()``
    gives the study's dataset again, identical; ``compact`` stores the study
    to its :data:`~stackup.study.schema.STORED_RESOLUTION` instead (a file
    about a quarter of the size, values within half the resolution: 5 nm,
    5 kPa; :func:`save`).
    """
    path = save(comparison.dataset, path, compact=compact)
    for k, (label, ds) in enumerate(comparison.scenarios.items()):
        save(ds.assign_attrs(scenario=label), path, group=f"scenario_{k}")
    save(comparison.sensitivity, path, group="sensitivity")
    save(comparison.tails, path, group="tails")
    return path


def open_comparison(path):
    """The :class:`~stackup.comparison.Comparison` saved in ``path``, in memory."""
    groups = _groups(Path(path))
    scenarios = {}
    for name in sorted((g for g in groups if g.startswith("scenario_")), key=lambda g: int(g.split("_")[1])):
        ds = open_dataset(path, group=name)
        scenarios[ds.attrs.pop("scenario")] = ds
    return Comparison(open_dataset(path), scenarios, open_dataset(path, group="sensitivity"),
                      open_dataset(path, group="tails"))


def _groups(path):
    """Names of the groups directly under the root of a netCDF file or Zarr store."""
    if path.suffix == ".zarr":
        import zarr

        return [name for name, _ in zarr.open_group(str(path), mode="r").groups()]
    import netCDF4

    with netCDF4.Dataset(path) as nc:
        return list(nc.groups)
