"""A damaged study store: find what cannot be read, name it, and mark it to be computed again.

A Zarr chunk of a study store (:mod:`stackup.study.store`) that cannot be
decoded (a truncated or overwritten file, a bad copy) would fail deep inside
the codec ("blosc decompression: -1"). Here such a chunk is named by its
variable, its file and the study chunk that wrote it, with the recovery:

- a per-engine variable or the small state of a study chunk: :func:`repair`
  drops that study chunk's completion mark, so running the same study with
  the same store computes that chunk again (and rewrites its Zarr chunks)
  and keeps every other chunk;
- a variable written when the study ends (scheme limits, shell counters):
  running the study again rewrites it;
- the engine coordinate: :func:`repair` rewrites it (it is 0, 1, 2, ...);
- the running total of a ``keep="summaries"`` study: :func:`repair` drops
  it, so the study starts its summaries again.

:func:`check` reads every chunk once (``stackup store check PATH``);
:func:`repair` applies the recoveries (``stackup store repair PATH``).
:func:`named_reads` makes the lazily opened dataset of a store raise
:class:`DamagedStore` with the same words when a damaged chunk is read.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

#: The bookkeeping group of a study store (:class:`stackup.study.store.ChunkStore`).
BOOK = "chunks"
#: Index coordinates along the engines, whose values are the engine numbers.
ENGINE_COORDS = ("engine", "mech_engine")


class DamagedStore(ValueError):
    """A chunk of a store cannot be read; the message names it and says how to recover."""


@dataclass(frozen=True)
class Damage:
    """One Zarr chunk of a store that cannot be read.

    Attributes
    ----------
    variable : str
        Path of the array in the store (``"clearance_operating"``,
        ``"chunks/000020/shells/made"``).
    chunk : tuple of int
        Index of the Zarr chunk in the array's chunk grid.
    file : str
        The chunk's file, relative to the store.
    error : str
        Why it cannot be read.
    study_chunk : int or None
        First production lot of the study chunk that wrote it (the name of
        its bookkeeping group), when recomputing that chunk recovers it.
    engines : (int, int) or None
        Engines (or mechanical-chain engines) the Zarr chunk holds, [start, stop).
    recovery : str
        ``"recompute"`` (drop the study chunk's mark), ``"rerun"`` (written
        again when the study runs again), ``"coordinate"`` (rewritten by
        :func:`repair`), ``"restart"`` (the summaries' running total is
        dropped) or ``"none"`` (not a study store: save it again).
    """

    variable: str
    chunk: tuple
    file: str
    error: str
    study_chunk: int | None
    engines: tuple | None
    recovery: str

    def where(self):
        """The damaged chunk in words."""
        text = f"variable {self.variable!r}, Zarr chunk {self.file}"
        extra = []
        if self.engines is not None:
            extra.append(f"engines {self.engines[0]} to {self.engines[1] - 1}")
        if self.study_chunk is not None:
            extra.append(f"study chunk {self.study_chunk:06d}")
        return text + (f" ({', '.join(extra)})" if extra else "")

    def remedy(self, path):
        """What recovers it, in words."""
        repair_cmd = f"`stackup store repair {path}`"
        if self.recovery == "recompute":
            return (f"run {repair_cmd} to mark study chunk {self.study_chunk:06d} to be computed again, then run the "
                    "same study with the same store: it recomputes that chunk and keeps the rest")
        if self.recovery == "rerun":
            return "run the same study with the same store again: it rewrites this variable at the end"
        if self.recovery == "coordinate":
            return f"run {repair_cmd}: it rewrites the engine numbers"
        if self.recovery == "restart":
            return (f"run {repair_cmd} to drop the saved running total, then run the same study with the same "
                    "store: its summaries start again")
        return "this store was saved whole, not streamed by a study: save the dataset again"


def _open(path, mode="r"):
    import zarr

    try:
        return zarr.open_group(str(path), mode=mode, zarr_format=3)
    except Exception as error:  # a missing folder, or one that is not a Zarr 3 group
        raise ValueError(f"store: {str(path)!r} is not a Zarr store ({error})") from None


def _study(root):
    """The study parameters recorded in a store's bookkeeping, or None for a store not streamed by a study."""
    try:
        return json.loads(root[BOOK].attrs["study"])["study"]
    except (KeyError, TypeError, ValueError):
        return None


def _chunk_file(array, index):
    return f"{array.path}/{array.metadata.encode_chunk_key(tuple(int(i) for i in index))}"


def describe(root, variable, index, error):
    """The :class:`Damage` of chunk ``index`` of array ``variable`` (its path in the store ``root``)."""
    array = root[variable]
    file = _chunk_file(array, index)
    study, parts = _study(root), variable.split("/")
    total = root[BOOK].attrs.get("total") if BOOK in root else None
    engines = first = None
    if study is None:
        recovery = "none"
    elif parts[0] == BOOK:
        if parts[1].isdigit():
            first, recovery = int(parts[1]), "recompute"
        elif total and total.get("slot") == parts[1]:
            recovery = "restart"
        else:
            recovery = "rerun"  # the slot not in use: written over at the next save
    elif variable in ENGINE_COORDS:
        recovery = "coordinate"
    else:
        dims = list(array.metadata.dimension_names or ())
        along = [d for d in ENGINE_COORDS if d in dims]
        if along:
            axis = dims.index(along[0])
            size = array.chunks[axis]
            k = int(index[axis])
            engines = (k * size, min((k + 1) * size, array.shape[axis]))
            first, recovery = k * int(study["chunk_lots"]), "recompute"
        else:
            recovery = "rerun"
    return Damage(variable, tuple(int(i) for i in index), file, str(error) or type(error).__name__, first, engines,
                  recovery)


def _arrays(group, prefix=""):
    """(path, array) of every array under ``group``, recursively."""
    for name, array in group.arrays():
        yield prefix + name, array
    for name, sub in group.groups():
        yield from _arrays(sub, f"{prefix}{name}/")


def check(path):
    """Every chunk of the store at ``path`` that cannot be read, as a list of :class:`Damage` (empty: sound).

    Reads every chunk once: one row of chunks along the first axis at a
    time, and chunk by chunk where a row fails.
    """
    root = _open(path)
    _check_metadata(path)
    damages = []
    for variable, array in _arrays(root):
        grid = array.cdata_shape
        if array.size == 0:
            continue
        rows = range(grid[0]) if grid else [None]
        for row in rows:
            try:
                array[...] if row is None else array.get_block_selection((row,))
                continue
            except Exception:
                pass
            inner = [()] if row is None else [(row, *rest) for rest in np.ndindex(*grid[1:])]
            for index in inner:
                try:
                    array.get_block_selection(index)
                except Exception as error:
                    damages.append(describe(root, variable, index, error))
    return damages


def _check_metadata(path):
    """Raise :class:`DamagedStore` naming a metadata file (``zarr.json``) that is not valid JSON: no chunk-wise repair."""
    for meta in sorted(Path(path).rglob("zarr.json")):
        try:
            json.loads(meta.read_bytes())
        except (ValueError, OSError) as error:
            raise DamagedStore(f"store {str(path)!r} is damaged: its metadata file {str(meta.relative_to(path))!r} "
                               f"cannot be read ({error}); this cannot be repaired chunk by chunk: delete the store "
                               "and run the study again") from None


def repair(path):
    """Mark what :func:`check` finds damaged to be recovered; return the :class:`Damage` list.

    Drops the completion mark of each study chunk that wrote a damaged
    chunk (its files stay, so reading them still fails until the study runs
    again and rewrites them, never reading as zeros), rewrites a damaged
    engine coordinate and drops a damaged running total of summaries.
    Damage that only running the study again (or saving again) recovers is
    returned unchanged.
    """
    damages = check(path)
    root = _open(path, mode="r+")
    for damage in damages:
        if damage.recovery == "recompute":
            group = root[BOOK].get(f"{damage.study_chunk:06d}")
            if group is not None:
                group.attrs["complete"] = False
        elif damage.recovery == "coordinate":
            array = root[damage.variable]
            array[...] = np.arange(array.shape[0], dtype=array.dtype)
        elif damage.recovery == "restart":
            attrs = dict(root[BOOK].attrs)
            attrs.pop("total", None)
            root[BOOK].attrs.clear()
            root[BOOK].attrs.update(attrs)
    return damages


def damaged_state(path, variable, error):
    """:class:`DamagedStore` for an unreadable array of the bookkeeping (whole array: one chunk)."""
    root = _open(path)
    damage = describe(root, variable, (0,) * root[variable].ndim, error)
    return DamagedStore(f"store {str(path)!r} is damaged: {damage.where()} cannot be read ({damage.error}); to "
                        f"recover, {damage.remedy(path)}")


class _NamedChunks:
    """A stored variable whose chunk reads raise :class:`DamagedStore` naming the chunk (for ``dask.array.from_array``)."""

    def __init__(self, variable, path, group, name, chunks):
        self.variable, self.path, self.group, self.name, self.chunks = variable, path, group, name, chunks
        self.shape, self.dtype, self.ndim = variable.shape, variable.dtype, variable.ndim

    def __getitem__(self, key):
        try:
            return np.asarray(self.variable[key].values)
        except Exception as error:
            index = tuple((k.start or 0) // c if isinstance(k, slice) else int(k) // c for k, c in zip(key, self.chunks))
            raise self._damaged(index, error) from error

    def _damaged(self, index, error):
        try:
            root = _open(self.path)
            variable = f"{self.group}/{self.name}" if self.group else self.name
            damage = describe(root, variable, index, error)
        except Exception:  # describing failed too: say what we know
            return DamagedStore(f"store {str(self.path)!r}: variable {self.name!r}, chunk {index} cannot be read "
                                f"({error}); `stackup store check {self.path}` lists what is damaged")
        return DamagedStore(f"store {str(self.path)!r} is damaged: {damage.where()} cannot be read ({damage.error}); "
                            f"to recover, {damage.remedy(self.path)}")


def named_reads(ds, path, group=None):
    """``ds`` (opened from the store at ``path`` without dask) with each variable read chunk by chunk through dask,
    a chunk that cannot be read raising :class:`DamagedStore` that names it and the recovery."""
    import dask.array as da

    data = {}
    for name, var in ds.data_vars.items():
        if var.ndim == 0:
            continue
        chunks = var.encoding.get("preferred_chunks")
        chunks = tuple(chunks[d] for d in var.dims) if chunks else var.encoding.get("chunks", var.shape)
        reader = _NamedChunks(var.variable, path, group, name, chunks)
        data[name] = var.copy(data=da.from_array(reader, chunks=chunks, name=False, asarray=True,
                                                 meta=np.empty((0,) * var.ndim, dtype=var.dtype)))
    return ds.assign(data)


@dataclass(frozen=True)
class StoreStatus:
    """What a study store holds.

    Attributes
    ----------
    study : dict or None
        The study's parameters (None: not a store streamed by a study).
    chunks_done : int
        Study chunks written whole (``keep="everything"``), or chunks the
        saved running total holds (``keep="summaries"``; 0 when none saved).
    chunks_total : int or None
        Study chunks of the whole study, where the store tells.
    finished : bool
        The study ran to its end (its dataset attributes are written).
    """

    study: dict | None
    chunks_done: int
    chunks_total: int | None
    finished: bool


def status(path):
    """The :class:`StoreStatus` of the store at ``path``."""
    root = _open(path)
    _check_metadata(path)
    study = _study(root)
    finished = "stackup_version" in root.attrs
    if study is None:
        return StoreStatus(None, 0, None, finished)
    book = root[BOOK]
    if study.get("keep") == "summaries":
        total = book.attrs.get("total")
        done = -(-int(total["next"]) // int(study["chunk_lots"])) if total else 0
        return StoreStatus(study, done, done if finished and total else None, finished)
    done = sum(1 for _, group in book.groups() if group.attrs.get("complete"))
    totals = [array.cdata_shape[list(array.metadata.dimension_names).index("engine")]
              for _, array in root.arrays() if "engine" in (array.metadata.dimension_names or ()) and array.ndim > 1]
    return StoreStatus(study, done, totals[0] if totals else None, finished)
