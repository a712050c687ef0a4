"""Where finished chunks go: the whole dataset in memory, the whole dataset in a Zarr store, or summaries.

A sink receives chunk results (:class:`~stackup.study.chain.ChunkResult`, or
:class:`~stackup.study.summaries.ChunkSummary` for ``keep="summaries"``)
as they finish, resumes from a store, and returns the study's dataset.
"""

from __future__ import annotations

import json
import time

import numpy as np
import xarray as xr

from ..film.cycle import film_method_errors
from .._version import __version__
from ..tolerances import DISTRIBUTION_NAMES, process_mean, quantile_cpk
from . import schema
from . import summaries as summarise
from .chain import ChunkResult, MechanicsProgress, ShellCounts
from .store import open_study, to_stored

#: Least time between two saves of the running total of a ``keep="summaries"`` study in its store [s]:
#: a resumed study recomputes at most the chunks finished in this time.
SUMMARY_CHECKPOINT_SECONDS = 30.0


def sink(study, ctx, store):
    """The sink of ``study``: summaries, or every engine in memory or in ``store`` (a ChunkStore or None)."""
    if study.keep == "summaries":
        return SummarySink(study, ctx, store)
    return MemorySink(study, ctx) if store is None else StoreSink(study, ctx, store)


class Progress:
    """The mechanical chain's progress over the chunks added so far, in engine order."""

    def __init__(self):
        self.state = MechanicsProgress()
        self._h_min = []

    def add(self, progress, h_min_head):
        self.state.next = max(self.state.next, progress.next)  # chunks may arrive in any order
        self.state.done = self.state.done or bool(progress.done)
        if h_min_head.shape[1]:
            self._h_min.append(h_min_head)

    def h_min_before(self):
        return np.concatenate(self._h_min, axis=1) if self._h_min else None

    def for_next_chunk(self):
        """What a ``target_error`` study's next chunk needs: (MechanicsProgress, h_min of the engines before)."""
        return self.state, self.h_min_before()


def full_dataset(study, ctx, per_engine, per_mech, shells, mechanics_used):
    """The dataset of a study that keeps every engine, each variable as :data:`schema.FULL` declares it.

    ``per_mech`` holds the mechanical chain's variables of its first
    ``mechanics_used`` engines (longer arrays are cut there).
    """
    engine, schemes, grade_labels = ctx.engine, ctx.schemes, ctx.grade_labels
    n, b = per_engine["block_scrapped"].size, engine.main_bearings
    in_scheme = np.array([[lab in s.shell.labels for lab in grade_labels] for s in schemes])
    used = {name: value[:, :mechanics_used] for name, value in per_mech.items()}
    values = {**per_engine, **used, "shells_made": shells.made, "shells_used": shells.used, "shells_left": shells.left,
              "shells_scrapped": shells.scrapped, "grade_in_scheme": in_scheme}
    fixed = {**schema.scheme_variables(schemes), **schema.design_variables(engine)}
    data = {name: fixed[name] if name in fixed else var(values[name]) for name, var in schema.FULL.items()}
    data.update({name: fixed[name] for name in schema.DESIGN})
    coords = schema.coords(scheme=[s.name for s in schemes], engine=np.arange(n), bearing=np.arange(1, b + 1),
                           shell_grade=grade_labels, bound=schema.BOUNDS, axis=schema.AXES, part=schema.PARTS,
                           mech_engine=np.arange(mechanics_used))
    if study.history:
        data.update({name: var(used[name]) for name, var in schema.HISTORY.items()})
        coords.update(schema.coords(crank_angle=ctx.crank_angle))
    attrs = {"title": f"Selective assembly of {engine.title or engine.name}", **attributes(study, ctx, mechanics_used)}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def processes(engine):
    """How the engine's parts are made and read, as plain data in SI units (keys say the unit)."""
    def dimension(dim):
        mean, std = float(process_mean(dim.process)), float(dim.process.std)
        # the engine file's name of the distribution and ISO 22514-2's quantile C_pk: for a normal process the
        # classic min(U - mu, mu - L) / 3 sigma; for a skewed or two-machine one the tail the limits face
        return {"limits_m": [dim.lo, dim.hi], "distribution": DISTRIBUTION_NAMES[type(dim.process)], "mean_m": mean,
                "std_m": std, "cpk": quantile_cpk(dim.process, dim.lo, dim.hi), "shared": dim.shared,
                "gauge_repeatability_m": dim.gauge.repeatability, "gauge_resolution_m": dim.gauge.resolution}

    supply = engine.shell_wall
    out = {"housing_bore": dimension(engine.housing_bore), "journal_d": dimension(engine.journal_d),
           "shell_wall": {"supply": supply.mode, "sigma_m": supply.sigma, "target_offset_m": supply.target_offset,
                          "gauge_repeatability_m": supply.gauge.repeatability,
                          "gauge_resolution_m": supply.gauge.resolution, "lot_engines": supply.lot_engines,
                          "surplus": supply.surplus},
           "crush_height": dimension(supply.crush)}
    crank = engine.crank
    if crank is not None:
        out["crank"] = {"speed_rpm": crank.speed * 30 / np.pi, "bearing_width_m": crank.bearing_width,
                        "coaxiality_m": crank.coaxiality, "journal_runout_m": crank.journal_runout,
                        "oil": getattr(crank.oil, "name", crank.oil), "oil_supply_temperature_degC": crank.oil_supply_temperature}
    return out


def attributes(study, ctx, mechanics_used):
    """Attributes of every study dataset: the parameters that reproduce it and the engine data reports quote."""
    engine = ctx.engine
    return {
        "stackup_version": __version__,
        "study": json.dumps(study.parameters()),
        "seed": study.seed,
        "engine": engine.name,
        "engine_source": engine.source,
        "lot_engines": engine.shell_wall.lot_engines,
        "shell_surplus": engine.shell_wall.surplus,
        "shell_supply": engine.shell_wall.mode,
        "pilot_engines": study.pilot_engines,
        "film_method_used": ctx.film_method,
        "film_method_errors": json.dumps(film_method_errors(ctx.film_method)),
        "mechanics_engines_used": mechanics_used,
        "scheme_sources": json.dumps({s.name: s.source for s in ctx.schemes}),
        "press_fit": json.dumps(engine.press_fit.record()),
        "press_fit_limits_source": engine.press_fit_limits.source,
        "input_files": json.dumps(study.files),
        "crush_height_source": engine.press_fit.crush_source,
        "clearance_window_source": engine.clearance_window_source,
        "minimum_clearance_source": engine.minimum_clearance_source,
        "cold_start_source": engine.press_fit.cold_start_source,
        "engine_processes": json.dumps(processes(engine)),
        "wear": json.dumps({"journal_rz_m": engine.wear.journal_rz, "shell_rz_m": engine.wear.shell_rz,
                            "journal_rq_m": engine.wear.journal_rq, "shell_rq_m": engine.wear.shell_rq,
                            "critical_film_m": engine.wear.critical_film, "wear_limit_m": engine.wear.wear_limit,
                            "method1_wear_limit_m": engine.wear.method1_wear_limit,
                            "wear_rate_m_per_s": engine.wear.wear_rate, "lining_material": engine.wear.lining_material,
                            "roughness_source": engine.wear.roughness_source, "wear_source": engine.wear.wear_source}),
        "oil_feed_source": engine.oil_feed.source,
        "Conventions": "CF-1.10",
    }


def _arrays(study, ctx, n_engines, n_mech):
    """Empty per-engine arrays of ``n_engines`` engines and mechanical-chain arrays of ``n_mech`` engines."""
    sizes = {"scheme": len(ctx.schemes), "engine": n_engines, "bearing": ctx.engine.main_bearings, "axis": 2,
             "mech_engine": n_mech, "crank_angle": ctx.crank_angle.size}
    mech = schema.PER_MECH if study.history else schema.MECHANICS
    return ({name: var.empty(sizes) for name, var in schema.PER_ENGINE.items()},
            {name: var.empty(sizes) for name, var in mech.items()})


class MemorySink:
    """Every engine of the study in memory."""

    def __init__(self, study, ctx):
        self.study, self.ctx = study, ctx
        self.progress = Progress()
        self.per_engine, self.per_mech = _arrays(study, ctx, study.n_engines, ctx.mechanics)
        self.shells = ShellCounts.zeros(len(ctx.schemes), len(ctx.grade_labels))

    def resume(self):
        return set()

    def add(self, result):
        self.progress.add(result.progress, result.h_min_head)
        rows = slice(result.engines.start, result.engines.stop)
        for name, value in result.per_engine.items():
            self.per_engine[name][(slice(None),) * schema.PER_ENGINE[name].engine_axis + (rows,)] = value
        for name, value in result.per_mech.items():
            self.per_mech[name][:, rows] = value  # the first engines only: the slice is shorter or empty
        self.shells.add(result.shells)

    def result(self):
        return full_dataset(self.study, self.ctx, self.per_engine, self.per_mech, self.shells, self.progress.state.next)


def _no_coords(ds):
    return ds.drop_vars(list(ds.coords))


def _per_engine(ds):
    """The variables of ``ds`` that run along the engines (``engine`` or ``mech_engine``)."""
    return ds[[k for k, v in ds.data_vars.items() if {"engine", "mech_engine"} & set(v.dims)]]


class StoreSink:
    """Every engine of the study in a Zarr store (:class:`~stackup.study.store.ChunkStore`), chunk by chunk."""

    def __init__(self, study, ctx, store):
        self.study, self.ctx, self.store = study, ctx, store
        self.progress = Progress()
        self.shells = ShellCounts.zeros(len(ctx.schemes), len(ctx.grade_labels))
        self.labels = {lab for s in ctx.schemes for grades in (s.housing, s.journal, s.shell) for lab in grades.labels}
        # one engine's dataset: the variables, dimensions, attributes and order of the stored one
        self.layout = self._dataset(*_arrays(study, ctx, 1, 1), mechanics_used=1)
        if not store.has_template:
            store.write_template(self._template())

    def _dataset(self, per_engine, per_mech, mechanics_used):
        return full_dataset(self.study, self.ctx, per_engine, per_mech, self.shells, mechanics_used)

    def _template(self):
        """The stored per-engine variables, full size and empty (dask), chunked like the study."""
        import dask.array as da

        study, ctx, one = self.study, self.ctx, self.layout
        step = study.chunk_lots * ctx.lot
        sizes = {"engine": study.n_engines, "mech_engine": ctx.mechanics}
        variables = {}
        for name, var in to_stored(_per_engine(one), self.labels).data_vars.items():
            shape = tuple(sizes.get(d, s) for d, s in zip(var.dims, var.shape))
            chunks = tuple(step if d in sizes else s for d, s in zip(var.dims, shape))
            # one dask chunk (a small graph however large the study); the Zarr chunks follow the study's
            variables[name] = xr.Variable(var.dims, da.empty(shape, dtype=var.dtype, chunks=shape), var.attrs,
                                          encoding={"chunks": chunks})
        coords = schema.coords(engine=np.arange(study.n_engines), mech_engine=np.arange(ctx.mechanics))
        template = xr.Dataset(variables, coords=coords)
        return to_stored(template.assign_coords({k: v for k, v in one.coords.items() if k not in sizes}))

    def resume(self):
        """Add the chunks the store holds; return their numbers."""
        finished = self.store.finished()
        for first in sorted(finished):
            state = self.store.read_state(first)
            self._count(MechanicsProgress(int(state["progress"][0]), bool(state["progress"][1])),
                        state["h_min_head"], ShellCounts(**state["shells"]))
        return finished

    def _count(self, progress, h_min_head, shells):
        self.progress.add(progress, h_min_head)
        self.shells.add(shells)

    def add(self, result):
        self._count(result.progress, result.h_min_head, result.shells)
        e0, e1 = result.engines.start, result.engines.stop
        mechanical = result.per_mech["h_min"].shape[1]
        ds = to_stored(_per_engine(self._dataset(result.per_engine, result.per_mech, mechanical)), self.labels)
        engine_vars = [k for k, v in ds.data_vars.items() if "engine" in v.dims]
        self.store.write_region(_no_coords(ds[engine_vars]), {"engine": slice(e0, e1)})
        if mechanical:
            mech_vars = [k for k, v in ds.data_vars.items() if "mech_engine" in v.dims]
            self.store.write_region(_no_coords(ds[mech_vars]), {"mech_engine": slice(e0, e0 + mechanical)})
        self.store.write_state(result.first, {
            "shells": vars(result.shells), "h_min_head": result.h_min_head,
            "progress": np.array([result.progress.next, int(result.progress.done)])})

    def result(self):
        used = self.progress.state.next
        whole = self._dataset(*_arrays(self.study, self.ctx, 0, 0), mechanics_used=0).assign_attrs(
            mechanics_engines_used=used)
        self.store.write_rest(to_stored(whole.drop_vars([*_per_engine(whole).data_vars, "engine", "mech_engine"])))
        return open_study(self.store.path)[list(self.layout.data_vars)]


class SummarySink:
    """Adds the lot summaries of a ``keep="summaries"`` study in lot order; saves the running total in the store."""

    def __init__(self, study, ctx, store):
        self.study, self.ctx, self.store = study, ctx, store
        self.progress = Progress()
        self.total = None
        self.sample = []
        self.waiting = {}
        self.queue = list(range(0, ctx.n_lots, study.chunk_lots))
        self.saved_at = time.monotonic()

    def resume(self):
        """Start from the total saved in the store; return the numbers of the chunks it holds."""
        saved = self.store.read_total() if self.store is not None else None
        if saved is None:
            return set()
        state, next_first = saved
        self.total = summarise.Summary(**state["total"])
        self.sample = [state["sample"]]
        self.progress.add(MechanicsProgress(int(state["progress"][0]), bool(state["progress"][1])),
                          state["h_min_head"])
        finished = {first for first in self.queue if first < next_first}
        self.queue = [first for first in self.queue if first >= next_first]
        return finished

    def add(self, chunk):
        self.waiting[chunk.first] = chunk
        # add the chunks that are next in order; out-of-order chunks wait
        while self.queue and self.queue[0] in self.waiting:
            chunk = self.waiting.pop(self.queue.pop(0))
            for lot in chunk.lots:
                self.total = lot.copy() if self.total is None else self.total.add(lot)
            self.sample.append(chunk.sample)
            self.progress.add(chunk.progress, chunk.h_min_head)
        if self.store is not None and time.monotonic() - self.saved_at >= SUMMARY_CHECKPOINT_SECONDS:
            self._save()

    def _save(self):
        if self.total is None:
            return
        sample = self._sample()
        head = self.progress.h_min_before()
        self.store.write_total({
            "total": self.total.arrays(), "sample": sample,
            "progress": np.array([self.progress.state.next, int(self.progress.state.done)]),
            "h_min_head": head if head is not None else sample["h_min"][:, :0],
        }, self.queue[0] if self.queue else self.ctx.n_lots)
        self.sample = [sample]
        self.saved_at = time.monotonic()

    def _sample(self):
        return {k: np.concatenate([piece[k] for piece in self.sample], axis=1) for k in self.sample[0]}

    def result(self):
        ctx = self.ctx
        if self.store is not None:
            self._save()  # a rerun of the finished study only reads the total
        used = self.progress.state.next
        sample = {k: v[:, :used] for k, v in self._sample().items()}
        attrs = {"title": f"Streaming summaries of selective assembly of {ctx.engine.title or ctx.engine.name}",
                 **attributes(self.study, ctx, used), "bin_width": summarise.BIN_WIDTH}
        ds = summarise.dataset(self.total, sample, schemes=ctx.schemes, grade_labels=ctx.grade_labels, attrs=attrs)
        ds = ds.assign(schema.design_variables(ctx.engine))
        if self.store is not None:
            self.store.write_rest(to_stored(ds))
        return ds


__all__ = ["ChunkResult", "MemorySink", "StoreSink", "SummarySink", "full_dataset", "sink"]
