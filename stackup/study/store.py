"""The Zarr store a study streams into, chunk by chunk, and resumes from.

Layout of a store (Zarr format 3, one folder):

- the root group is the study dataset, as xarray writes it: with
  ``keep="everything"`` the per-engine variables are created empty when the
  study starts and each finished chunk fills its own engine range (its own
  Zarr chunks, so no two writes touch the same chunk); the remaining variables
  (shell counters, scheme limits) and the attributes follow when the study
  ends. With ``keep="summaries"`` the summary dataset is written at the end.
- the group ``chunks`` is the bookkeeping: its attribute ``study`` is the study
  fingerprint (a store holding another study is refused). With
  ``keep="everything"`` one subgroup per finished chunk holds that chunk's
  small state (shell counters, progress of the mechanical chain), marked
  ``complete`` only after everything of the chunk is written, so a chunk is
  either whole or computed again on a rerun. With ``keep="summaries"`` the
  running total of the chunks added so far (in lot order) is saved now and
  then into one of two slots, the pointer to it switched last. Either way
  nothing is lost or counted twice.

Grade labels are stored as int8 codes into a label list kept with each
variable, and :func:`open_study` turns them back into the fixed-width strings
of an in-memory study.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import xarray as xr

from .damage import damaged_state, named_reads
from .schema import LABEL_DTYPE

#: How string coordinates are stored: variable-length UTF-8, the string type Zarr 3 specifies.
STORED_STRING = np.dtypes.StringDType()
#: Attribute of a stored label variable: the labels its int8 codes index.
LABELS_ATTR = "stackup_labels"
_BOOK = "chunks"


class ChunkStore:
    """A study's Zarr store at ``path`` for the study with ``fingerprint``."""

    def __init__(self, path, fingerprint):
        import zarr

        self.path = Path(path)
        try:
            root = zarr.open_group(str(self.path), mode="a", zarr_format=3)
        except Exception as error:  # a folder that is not a Zarr 3 group
            raise ValueError(f"store: {str(self.path)!r} cannot be opened as a Zarr group ({error})") from error
        book = root.require_group(_BOOK)
        stamp = book.attrs.get("study")
        if stamp is None:
            if any(True for _ in root.arrays()):
                raise ValueError(f"store: {str(self.path)!r} holds data that is not a stackup study; use another path")
            book.attrs["study"] = fingerprint
        elif stamp != fingerprint:
            raise ValueError(f"store: {str(self.path)!r} holds chunks of another study "
                             "(parameters or stackup version differ); use another path or delete it")
        self._book = book

    def finished(self):
        """Numbers of the chunks written whole, as a set of their first lots."""
        return {int(name) for name, group in self._book.groups() if group.attrs.get("complete")}

    def read_state(self, first):
        """The small state saved with chunk ``first``."""
        return _read_arrays(self._book[f"{first:06d}"], self.path)

    def write_state(self, first, state):
        """Save chunk ``first``'s small state and mark the chunk complete (last)."""
        group = self._book.require_group(f"{first:06d}")
        group.attrs["complete"] = False
        _write_arrays(group, state)
        group.attrs["complete"] = True

    def write_total(self, total, next_first):
        """Save a running total (nested dicts of arrays) that holds every chunk before chunk ``next_first``.

        Written into the slot not in use, then the pointer is switched (last):
        an interruption leaves the previous total whole.
        """
        saved = self._book.attrs.get("total")
        slot = "total-b" if saved and saved["slot"] == "total-a" else "total-a"
        _write_arrays(self._book.require_group(slot), total)
        self._book.attrs["total"] = {"slot": slot, "next": int(next_first)}

    def read_total(self):
        """(total, next_first) of the last saved running total, or None."""
        saved = self._book.attrs.get("total")
        if not saved:
            return None
        return _read_arrays(self._book[saved["slot"]], self.path), saved["next"]

    @property
    def has_template(self):
        return bool(self._book.attrs.get("template"))

    def write_template(self, template):
        """Create the per-engine variables of ``template`` (dask-backed, nothing computed)."""
        codecs = _fast(template)
        encoding = {name: {**var.encoding, **codecs.get(name, {})} for name, var in template.variables.items()}
        template.to_zarr(self.path, mode="a", compute=False, consolidated=False, zarr_format=3, encoding=encoding)
        self._book.attrs["template"] = True

    def write_region(self, ds, region):
        """Write the per-engine variables of one chunk into their ``region`` (dim -> slice)."""
        ds.to_zarr(self.path, mode="r+", region=region, consolidated=False, zarr_format=3)

    def write_rest(self, ds):
        """Write the variables that do not run along the engines, and the dataset's attributes."""
        ds.to_zarr(self.path, mode="a", consolidated=False, zarr_format=3)


def _write_arrays(group, arrays):
    """Write nested dicts of arrays into a Zarr group: an array per array, a subgroup per dict (replacing)."""
    for name, value in arrays.items():
        if isinstance(value, dict):
            _write_arrays(group.require_group(name), value)
            continue
        value = np.asarray(value)
        group.create_array(name, shape=value.shape, dtype=value.dtype, overwrite=True)[...] = value


def _read_arrays(group, path):
    """What :func:`_write_arrays` wrote: nested dicts of arrays (a damaged one raises DamagedStore naming it)."""
    return {**{name: _read_array(array, path) for name, array in group.arrays()},
            **{name: _read_arrays(sub, path) for name, sub in group.groups()}}


def _read_array(array, path):
    try:
        return array[...]
    except Exception as error:
        raise damaged_state(path, array.path, error) from error


def _fast(ds):
    """Encoding of every numeric variable: Blosc LZ4 with byte shuffle.

    Faster to write than Zarr's default Zstandard, and no larger on sampled
    dimensions, which barely compress.
    """
    from zarr.codecs import BloscCodec

    codec = BloscCodec(cname="lz4", clevel=5, shuffle="shuffle")
    return {name: {"compressors": (codec,)} for name, var in ds.variables.items() if var.dtype.kind in "biuf"}


def to_stored(ds, labels=()):
    """``ds`` as stored: label variables as int8 codes, other strings variable-length.

    A variable of fixed-width strings (the grade labels) becomes int8 codes
    into the sorted ``labels`` (plus ""), kept in its attribute
    :data:`LABELS_ATTR`: much faster to write than strings, and what
    :func:`open_study` decodes. String coordinates become variable-length
    strings, the string type Zarr 3 specifies.
    """
    table = np.array(sorted(set(labels) | {""}))
    coded = {}
    for name, var in ds.data_vars.items():
        if var.dtype.kind == "U":
            codes = np.clip(np.searchsorted(table, var.values), 0, table.size - 1)
            unknown = table[codes] != var.values
            if unknown.any():
                raise ValueError(f"{name}: label {str(var.values[unknown][0])!r} is not one of {table.tolist()}")
            coded[name] = xr.Variable(var.dims, codes.astype(np.int8), {**var.attrs, LABELS_ATTR: table.tolist()})
    strings = {k: ds[k].astype(STORED_STRING) for k, var in ds.coords.items() if var.dtype.kind == "U"}
    return ds.assign(coded).assign_coords(strings)


def open_study(path, *, group=None):
    """The study dataset in a store (or one of its groups), lazily (dask-backed): nothing is read until used.

    Grade labels come back as fixed-width strings, as in an in-memory study. A
    chunk that cannot be read raises :class:`~stackup.study.damage.DamagedStore`
    naming it and how to recover.
    """
    ds = named_reads(xr.open_zarr(Path(path), group=group, consolidated=False, zarr_format=3, chunks=None), path, group)
    labels = {}
    for name, var in ds.data_vars.items():
        if LABELS_ATTR in var.attrs:
            table = np.array(var.attrs[LABELS_ATTR], dtype=LABEL_DTYPE)
            attrs = {k: v for k, v in var.attrs.items() if k != LABELS_ATTR}
            labels[name] = xr.Variable(var.dims, var.data.map_blocks(table.__getitem__, dtype=table.dtype), attrs)
    coords = {name: (var.dims, np.array(var.values.tolist(), dtype=str), var.attrs) for name, var in ds.coords.items()
              if var.dtype == STORED_STRING or var.dtype == object}
    ds = ds.assign(labels).assign_coords(coords)
    if "mech_engine" in ds.dims and "mechanics_engines_used" in ds.attrs:
        # the store holds room for every engine the chain may run on; a target error may stop it earlier
        ds = ds.isel(mech_engine=slice(0, int(ds.attrs["mechanics_engines_used"])))
    return ds
