"""A study: one scenario (engine, schemes, size, seed) run into one xarray Dataset."""

from __future__ import annotations

import itertools
import json
import math
import os
import time
from dataclasses import asdict, dataclass

import numpy as np
import xarray as xr
from tqdm.auto import tqdm

from . import __version__
from . import _validate as check
from ._random import PILOT_KEY, lot_generator, seed_sequence
from .assembly import ASSEMBLED, STATUS, assemble, shell_demand
from .crank.cycle import CYCLE_STATUS, NOT_COMPUTED, engine_cycles, worst_status
from .crank.cycle import METHODS as CRANK_METHODS
from .film import cheapest_tier
from .film.cycle import bearing_films
from .fit import METHODS as FIT_METHODS
from .fit import press_fit
from .engines import load_engine
from .parts import SAMPLERS, draw_lot
from . import summaries as summarise
from .scenarios import apply as apply_scenario
from .schemes import load as load_scheme
from .store import ChunkStore, open_study, to_stored

ISO_SCHEMES = tuple(f"iso13778-{k}" for k in range(1, 7))


@dataclass
class Study:
    """A Monte Carlo study of selective assembly.

    Parameters
    ----------
    engine : str or path
        Built-in engine name or engine TOML file.
    schemes : sequence of str or path
        Scheme names or scheme TOML files.
    n_engines : int
        Engines to sample (each with its block, crankshaft and shells).
    seed : int
        Root seed; lot ``k`` uses child ``k`` of ``SeedSequence(seed)``.
    chunk_lots : int
        Lots processed together. Execution only: results do not depend on it.
    pilot_engines : int
        Engines of the pilot sample (own random stream) from which the shell
        quantity of each grade is planned.
    mechanics_engines : int
        Engines (the first ones sampled; lots are independent, so they are a
        random sample) on which the crankshaft beam, film and life run over
        the cycle; 0 skips the stage; with ``target_error`` it is the cap.
        Engines with a bearing not assembled are skipped and marked.
    keep : {"everything", "summaries"}
        Keep every engine, or only streaming summaries
        (:mod:`stackup.summaries`: histograms, counts, moments and extremes of
        the clearance and press-fit stages, shell counters, worst bearings,
        and the mechanical chain's results of the engines it runs on), so
        memory stays flat as ``n_engines`` grows. ``history`` is not kept
        with ``"summaries"``.
    history : bool
        Keep each mechanically computed engine's bearing loads and minimum
        film at every crank angle, on dimensions ``sampled_engine`` and
        ``crank_angle`` (large: 720 angles per bearing and scheme).
    target_error : float or None
        Run the mechanical chain only until the 95 % interval of each
        scheme's mean cycle-minimum film (engine means) is within this share
        of the mean, checked every 25 engines [-]; None runs
        ``mechanics_engines`` engines.
    crank_angle_step : float
        Step of the crank-angle grid over 720 deg [deg].
    fit_method : str
        Press-fit tier: "lame" (default), "thin-ring" or "fe" (slow reference).
    crank_method : str
        Crankshaft support tier: "bearing-law" (default), "linear" or "rigid".
    film_method : str
        Steady film tier of the quasi-static orbit on the engines of the
        crankshaft stage: "short", "finite" (default), "reynolds", or "auto"
        for the cheapest tier whose h_min error is within ``film_error``.
    film_error : float
        Largest h_min error against the Reynolds tier that "auto" accepts [-].
    progress : bool or None
        Show a progress bar; None shows one only on a terminal.
    sampler : {"mc", "qmc"}
        Pseudo-random Monte Carlo, or scrambled Sobol points for each
        engine's parts (randomised QMC, one scramble per lot).
    scenario : dict or None
        Disturbance of the engine's processes (:mod:`stackup.scenarios`), e.g.
        ``{"housing_shift": 1.0}`` for the bore mean one sigma up.
    store : str or None
        Path of a Zarr store the results stream into as chunks finish
        (:mod:`stackup.store`), so a study larger than memory can keep every
        engine; ``run`` then returns the dataset opened lazily from the store.
        It is also the checkpoint: a rerun of the same study with the same
        store computes only the chunks not yet written, so an interrupted study
        resumes without losing or repeating work. Execution only: results do
        not depend on it.
    """

    engine: str = "iso-example"
    schemes: tuple = ISO_SCHEMES
    n_engines: int = 100_000
    seed: int = 0
    chunk_lots: int = 20
    pilot_engines: int = 20_000
    mechanics_engines: int = 200
    target_error: float | None = None
    history: bool = False
    keep: str = "everything"
    crank_angle_step: float = 1.0
    fit_method: str = "lame"
    crank_method: str = "bearing-law"
    film_method: str = "finite"
    film_error: float = 0.05
    progress: bool | None = None
    sampler: str = "mc"
    scenario: dict | None = None
    store: str | None = None

    def __post_init__(self):
        self.n_engines = check.integer("n_engines", self.n_engines, minimum=1)
        self.chunk_lots = check.integer("chunk_lots", self.chunk_lots, minimum=1)
        self.pilot_engines = check.integer("pilot_engines", self.pilot_engines, minimum=1)
        self.mechanics_engines = check.integer("mechanics_engines", self.mechanics_engines, minimum=0)
        if self.target_error is not None:
            self.target_error = float(check.in_range("target_error", self.target_error, 0.0, 1.0, lo_open=True))
        self.crank_angle_step = float(check.in_range("crank_angle_step", self.crank_angle_step, 0.0, 90.0, lo_open=True))
        check.one_of("sampler", self.sampler, SAMPLERS)
        check.one_of("keep", self.keep, ("everything", "summaries"))
        check.one_of("fit_method", self.fit_method, FIT_METHODS)
        check.one_of("crank_method", self.crank_method, CRANK_METHODS)
        check.one_of("film_method", self.film_method, ("short", "finite", "reynolds", "auto"))
        self.film_error = float(check.in_range("film_error", self.film_error, 0.0, 1.0))
        if (720.0 / self.crank_angle_step) % 1:
            raise ValueError(f"crank_angle_step: {self.crank_angle_step!r} deg does not divide 720 deg")
        self.schemes = tuple(str(s) for s in self.schemes)
        if not self.schemes:
            raise ValueError("schemes: give at least one scheme")
        if len(set(self.schemes)) != len(self.schemes):
            raise ValueError(f"schemes: {list(self.schemes)!r} names a scheme twice")
        seed_sequence(self.seed)
        self.engine = str(self.engine)

    def parameters(self):
        """The study's parameters as plain data (stored in the dataset's attrs)."""
        return {k: v for k, v in asdict(self).items() if k not in ("progress", "store")}

    def _context(self):
        """Everything a chunk needs that follows from the parameters alone (cached per process)."""
        key = _fingerprint(self)
        if key not in _CONTEXTS:
            engine = apply_scenario(load_engine(self.engine), self.scenario)
            schemes = [load_scheme(s) for s in self.schemes]
            names = [s.name for s in schemes]
            if len(set(names)) != len(names):
                raise ValueError(f"schemes: two files carry the same scheme name ({names})")
            root = seed_sequence(self.seed)
            pilot, _ = draw_lot(engine, lot_generator(root, PILOT_KEY), self.pilot_engines)
            shares = []
            for s in schemes:
                demand = shell_demand(s, pilot)
                if demand.sum() == 0:
                    raise ValueError(f"scheme {s.name}: no bearing of the pilot sample could be graded; "
                                     "do the scheme's ranges match the engine's drawing limits?")
                shares.append(engine.shell_wall.aim_share(s, demand) if engine.shell_wall.mode == "to-order" else None)
            lot = engine.shell_wall.lot_engines
            _CONTEXTS.clear()  # one study at a time per process
            _CONTEXTS[key] = _Context(
                engine=engine, schemes=schemes, shares=shares, grade_labels=_union_labels(schemes), root=root,
                lot=lot, n_lots=math.ceil(self.n_engines / lot),
                mechanics=min(self.mechanics_engines, self.n_engines) if engine.crank is not None else 0,
                film_method=cheapest_tier(self.film_error) if self.film_method == "auto" else self.film_method,
                crank_angle=np.arange(0.0, 720.0, self.crank_angle_step))
        return _CONTEXTS[key]

    def _bounds(self, ctx, first):
        lots = range(first, min(first + self.chunk_lots, ctx.n_lots))
        return lots, lots[0] * ctx.lot, min((lots[-1] + 1) * ctx.lot, self.n_engines)

    def _output(self, ctx, engines, history_engines):
        return _Output(len(ctx.schemes), engines, ctx.engine.main_bearings, len(ctx.grade_labels),
                       history_engines if self.history else 0, ctx.crank_angle.size)

    def _fill(self, ctx, out, origin, first):
        """Compute chunk ``first`` into ``out``, whose engine 0 is engine ``origin`` of the study."""
        lots, e0, e1 = self._bounds(ctx, first)
        rows = slice(e0 - origin, e1 - origin)
        n = self.n_engines
        drawn = [draw_lot(ctx.engine, lot_generator(ctx.root, k), min(ctx.lot, n - k * ctx.lot), self.sampler)
                 for k in lots]
        parts = _concat_parts([p for p, _ in drawn])
        out.store_parts(rows, parts)
        stages = []
        for i, (scheme, share) in enumerate(zip(ctx.schemes, ctx.shares)):
            shells = [ctx.engine.shell_wall.make(scheme, normals, share) for _, normals in drawn]
            result = assemble(scheme, parts, shells, lot_engines=ctx.lot)
            out.store_assembly(i, rows, result, scheme, ctx.grade_labels)
            fit = _operating(ctx.engine, parts, result, self.fit_method)
            out.store_fit(i, rows, fit)
            stages.append((result, fit))
        # mechanical chain: engines in order, in batches at fixed engine numbers, until the
        # target error is met (decisions do not depend on the chunking)
        a = max(e0, out.mechanics_next)
        while not out.mechanics_done and a < min(e1, ctx.mechanics):
            stop = min(e1, ctx.mechanics, (a // MECHANICS_BATCH + 1) * MECHANICS_BATCH)
            for i, (result, fit) in enumerate(stages):
                out.store_crank(i, a - origin, _cycles(ctx.engine, parts, result, fit, slice(a - e0, stop - e0),
                                                       ctx.crank_angle, self.crank_method, ctx.film_method))
            a = out.mechanics_next = stop
            if a == ctx.mechanics or (self.target_error and a % MECHANICS_BATCH == 0
                                      and out.film_error(a) <= self.target_error):
                out.mechanics_done = True
        return e0, e1

    def chunk_state(self, first, progress=None):
        """Compute chunk ``first`` on its own (e.g. on a worker) and return its state for merging.

        ``progress`` is the mechanical chain's progress over the chunks before
        (a :class:`_Progress`); only a study with ``target_error`` needs it, in
        order. With ``keep="summaries"`` the state is the chunk's summary, one
        per production lot (:func:`stackup.summaries.reduce_chunk`).
        """
        ctx = self._context()
        lots, e0, e1 = self._bounds(ctx, first)
        summaries = self.keep == "summaries"
        local = self._output(ctx, e1 - e0, 0 if summaries else max(0, min(e1, ctx.mechanics) - e0))
        local.origin = e0
        if progress is None:
            local.mechanics_next = min(e0, ctx.mechanics)  # no engine past the mechanical range counts as progress
        else:
            local.mechanics_next, local.mechanics_done = progress.next, progress.done
            local.h_min_before = progress.h_min_before()
        before = local.counters()
        self._fill(ctx, local, e0, first)
        state = local.chunk_state(slice(0, e1 - e0), before)
        mechanical = max(0, min(e1, ctx.mechanics) - e0)  # engines of the chunk in the mechanical range
        head = {"mechanics.progress": state["mechanics.progress"],
                "mechanics.h_min_head": state["mechanics.h_min"][:, :mechanical].copy()}  # not a view: kept
        if summaries:
            # one summary per production lot: lots are fixed units, so the sums do not depend on the chunking
            reduced = [summarise.reduce_chunk(piece, e0=e0 + j * ctx.lot, window=ctx.engine.clearance_window,
                                              n_schemes=len(ctx.schemes))
                       for j, piece in enumerate(summarise.split_state(state, lots, ctx.lot))]
            lot_summaries = {f"lot.{k}": np.stack([r[k] for r in reduced]) for k in reduced[0]}  # lots first
            return {**lot_summaries, **summarise.mechanics_sample(state, mechanical), **head}
        return {**state, **head}

    def run(self, scheduler=None) -> xr.Dataset:
        """Sample, measure, grade, pair, assemble and run the stages; return the dataset.

        Parameters
        ----------
        scheduler : None, "processes" or dask.distributed.Client
            Where the chunks run: in this process, in local worker processes
            (a ``distributed.LocalCluster`` on loopback, one single-threaded
            worker per core, closed at the end), or on the dask cluster of the
            Client. Chunks are seeded from one SeedSequence, so the numbers are
            identical on all three. Results stream back as chunks finish, at
            most two chunks per worker in flight. ``target_error`` decides
            after each batch of engines in order and needs ``None``.

        Returns
        -------
        xarray.Dataset
            In memory; with ``store``, the dataset opened lazily from the store
            (dask-backed, read on use), except the small summary dataset.
        """
        ctx = self._context()
        if scheduler is not None and self.target_error:
            raise ValueError("scheduler: a study with target_error decides engine by engine in order; "
                             "run it with scheduler=None")
        if scheduler is not None and scheduler != "processes" and not (hasattr(scheduler, "submit")
                                                                      and hasattr(scheduler, "nthreads")):
            raise ValueError(f"scheduler: {scheduler!r} is not None, 'processes' or a dask.distributed Client")
        store = ChunkStore(self.store, _fingerprint(self)) if self.store is not None else None
        sink = (_SummarySink if self.keep == "summaries" else _DatasetSink)(self, ctx, store)
        firsts = list(range(0, ctx.n_lots, self.chunk_lots))
        with tqdm(total=len(firsts), unit="chunk", disable=_no_bar(self.progress), desc="study") as bar:
            finished = sink.resume()
            bar.update(len(finished))
            todo = [first for first in firsts if first not in finished]
            for first, state in _results(self, todo, scheduler, sink.progress):
                sink.add(first, state)
                bar.update(1)
        return sink.result()


class _Progress:
    """The mechanical chain's progress over the chunks added so far, in engine order."""

    def __init__(self):
        self.next = 0
        self.done = False
        self._h_min = []

    def add(self, state):
        done_to, done = (int(v) for v in state["mechanics.progress"])
        self.next = max(self.next, done_to)  # chunks may arrive in any order
        self.done = self.done or bool(done)
        if state["mechanics.h_min_head"].shape[1]:
            self._h_min.append(state["mechanics.h_min_head"])

    def h_min_before(self):
        return np.concatenate(self._h_min, axis=1) if self._h_min else None


#: Least time between two saves of the running total of a ``keep="summaries"`` study in its store [s]:
#: a resumed study recomputes at most the chunks finished in this time.
SUMMARY_CHECKPOINT_SECONDS = 30.0

#: Small per-chunk arrays kept in a store's bookkeeping (the rest goes into the dataset).
_SMALL = ("count.made", "count.used", "count.left", "count.scrapped", "mechanics.progress", "mechanics.h_min_head")


class _DatasetSink:
    """Receives finished chunks of a ``keep="everything"`` study: into memory, or into the store."""

    def __init__(self, study, ctx, store):
        self.study, self.ctx, self.store = study, ctx, store
        self.progress = _Progress()
        n = study.n_engines
        if store is None:
            self.out = study._output(ctx, n, ctx.mechanics)
            return
        self.out = study._output(ctx, 0, 0)  # the counters; the engines go to the store
        self.labels = {lab for s in ctx.schemes for grades in (s.housing, s.journal, s.shell) for lab in grades.labels}
        # one engine's dataset: the variables, dimensions, attributes and order of the stored one
        self.layout = self._dataset(study._output(ctx, 1, min(1, ctx.mechanics)))
        if not store.has_template:
            store.write_template(self._template())

    def resume(self):
        """Add the chunks the store holds; return their numbers."""
        finished = self.store.finished() if self.store is not None else set()
        for first in sorted(finished):
            self.add(first, self.store.read_state(first), stored=True)
        return finished

    def _dataset(self, out):
        ctx = self.ctx
        return out.dataset(self.study, ctx.engine, ctx.schemes, ctx.grade_labels, ctx.film_method, ctx.crank_angle)

    def _template(self):
        """The stored per-engine variables, full size and empty (dask), chunked like the study."""
        import dask.array as da

        study, ctx, one = self.study, self.ctx, self.layout
        step = study.chunk_lots * ctx.lot
        sizes = {"engine": study.n_engines, "sampled_engine": ctx.mechanics if study.history else 0}
        variables = {}
        for name, var in to_stored(_per_engine(one), self.labels).data_vars.items():
            shape = tuple(sizes.get(d, s) for d, s in zip(var.dims, var.shape))
            chunks = tuple(step if d in sizes else s for d, s in zip(var.dims, shape))
            # one dask chunk (a small graph however large the study); the Zarr chunks follow the study's
            variables[name] = xr.Variable(var.dims, da.empty(shape, dtype=var.dtype, chunks=shape), var.attrs,
                                          encoding={"chunks": chunks})
        coords = {"engine": ("engine", np.arange(study.n_engines), one.engine.attrs)}
        if study.history and ctx.mechanics:
            coords["sampled_engine"] = ("sampled_engine", np.arange(ctx.mechanics), one.sampled_engine.attrs)
        template = xr.Dataset(variables, coords=coords)
        return to_stored(template.assign_coords({k: v for k, v in one.coords.items() if k not in sizes}))

    def add(self, first, state, stored=False):
        _, e0, e1 = self.study._bounds(self.ctx, first)
        self.progress.add(state)
        if self.store is None:
            self.out.load_chunk(slice(e0, e1), state)
            return
        self.out.add_counts(state)
        if not stored:
            local = self.study._output(self.ctx, e1 - e0, state["history.h_min_history"].shape[1])
            local.load_chunk(slice(0, e1 - e0), state)
            ds = to_stored(_per_engine(self._dataset(local)), self.labels)
            engine_vars = [k for k, v in ds.data_vars.items() if "engine" in v.dims]
            self.store.write_region(_no_coords(ds[engine_vars]), {"engine": slice(e0, e1)})
            kept = local.history["h_min_history"].shape[1]
            if kept:
                history = [k for k, v in ds.data_vars.items() if "sampled_engine" in v.dims]
                self.store.write_region(_no_coords(ds[history]),
                                        {"sampled_engine": slice(e0, e0 + kept)})
            self.store.write_state(first, {k: state[k] for k in _SMALL})

    def result(self):
        self.out.mechanics_next = self.progress.next
        if self.store is None:
            return self._dataset(self.out)
        whole = self._dataset(self.out)
        self.store.write_rest(to_stored(whole.drop_vars([*_per_engine(whole).data_vars, "engine"])))
        return open_study(self.store.path)[list(self.layout.data_vars)]


def _prefixed(state, prefix):
    """The arrays of ``state`` whose names start with ``prefix``, by name without it."""
    return {k[len(prefix):]: v for k, v in state.items() if k.startswith(prefix)}


def _no_coords(ds):
    return ds.drop_vars(list(ds.coords))


def _per_engine(ds):
    """The variables of ``ds`` that run along the engines."""
    return ds[[k for k, v in ds.data_vars.items() if {"engine", "sampled_engine"} & set(v.dims)]]


class _SummarySink:
    """Adds the lot summaries of a ``keep="summaries"`` study in lot order; saves the running total in the store."""

    def __init__(self, study, ctx, store):
        self.study, self.ctx, self.store = study, ctx, store
        self.progress = _Progress()
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
        self.total = _prefixed(state, "lot.")
        self.sample = [_prefixed(state, "sample.")]
        self.progress.add(state)
        finished = {first for first in self.queue if first < next_first}
        self.queue = [first for first in self.queue if first >= next_first]
        return finished

    def add(self, first, state):
        self.waiting[first] = state
        # add the chunks that are next in order; out-of-order chunks wait
        while self.queue and self.queue[0] in self.waiting:
            state = self.waiting.pop(self.queue.pop(0))
            lots = _prefixed(state, "lot.")
            for lot in range(len(next(iter(lots.values())))):
                self.total = summarise.add(self.total, {k: v[lot] for k, v in lots.items()})
            self.sample.append(_prefixed(state, "sample."))
            self.progress.add(state)
        if self.store is not None and time.monotonic() - self.saved_at >= SUMMARY_CHECKPOINT_SECONDS:
            self._save()

    def _save(self):
        if self.total is None:
            return
        sample = self._sample()
        head = self.progress.h_min_before()
        self.store.write_total({
            **{f"lot.{k}": v for k, v in self.total.items()}, **{f"sample.{k}": v for k, v in sample.items()},
            "mechanics.progress": np.array([self.progress.next, int(self.progress.done)]),
            "mechanics.h_min_head": head if head is not None else sample["h_min"][:, :0],
        }, self.queue[0] if self.queue else self.ctx.n_lots)
        self.sample = [sample]
        self.saved_at = time.monotonic()

    def _sample(self):
        return {k: np.concatenate([piece[k] for piece in self.sample], axis=1) for k in self.sample[0]}

    def result(self):
        study, ctx = self.study, self.ctx
        attrs = {"stackup_version": __version__, "study": json.dumps(study.parameters()), "seed": study.seed,
                 "engine": ctx.engine.name, "clearance_window": list(ctx.engine.clearance_window),
                 "bin_width": summarise.BIN_WIDTH, "Conventions": "CF-1.10",
                 "title": f"Streaming summaries of selective assembly of {ctx.engine.title or ctx.engine.name}"}
        if self.store is not None:
            self._save()  # a rerun of the finished study only reads the total
        used = self.progress.next
        sample = {k: v[:, :used] for k, v in self._sample().items()}
        attrs["mechanics_engines_used"] = used
        attrs["film_method_used"] = ctx.film_method
        ds = summarise.dataset(self.total, sample, schemes=ctx.schemes, grade_labels=ctx.grade_labels, attrs=attrs)
        if self.store is not None:
            self.store.write_rest(to_stored(ds))
        return ds


#: Press-fit results stored per bearing: dataset name -> PressFit field.
FIT_FIELDS = {
    "contact_pressure": "contact_pressure",
    "shell_stress": "shell_stress",
    "housing_swell": "housing_swell",
    "bore_in_service": "bore_in_service",
    "clearance_operating": "clearance",
}


def _operating(engine, parts, assembly, method):
    """Press fit of the assembled bearings; NaN elsewhere (the status says why)."""
    ok = assembly.status == ASSEMBLED
    fit = press_fit(
        housing_bore=parts.housing_bore[ok],
        shell_wall=0.5 * (assembly.upper_wall[ok] + assembly.lower_wall[ok]),
        crush_height=0.5 * (assembly.upper_crush[ok] + assembly.lower_crush[ok]),
        journal_d=parts.journal_d[ok],
        method=method,
        **engine.press_fit.kwargs(),
    )
    out = {}
    for name, field in FIT_FIELDS.items():
        full = np.full(ok.shape, np.nan)
        full[ok] = getattr(fit, field)
        out[name] = full
    loss = np.zeros(ok.shape, bool)
    loss[ok] = fit.loss_of_fit
    out["loss_of_fit"] = loss
    return out


#: The study context of this process (see Study._context).
_CONTEXTS = {}


@dataclass(frozen=True)
class _Context:
    engine: object
    schemes: list
    shares: list
    grade_labels: list
    root: object
    lot: int
    n_lots: int
    mechanics: int
    film_method: str
    crank_angle: np.ndarray


def _chunk_task(study, first):
    """A chunk computed where the scheduler puts it (module level, so it pickles).

    A worker is one core: the numba kernels run on one thread there, so
    workers do not oversubscribe the machine.
    """
    import numba

    numba.set_num_threads(1)
    return first, study.chunk_state(first)


#: glibc malloc settings for the worker processes of ``scheduler="processes"`` (dask config keys).
#: The dask nanny sets MALLOC_TRIM_THRESHOLD_=65536, which also fixes glibc's mmap threshold at
#: 128 kB, so every large numpy array of a chunk is a fresh mmap with its page faults: 1.4x the CPU
#: time per chunk here. Arrays up to 16 MiB from the heap, trimmed past 64 MiB, cost less
#: (reports/bench_scale.md); set the same keys for the workers of your own cluster.
WORKER_MALLOC = {
    "distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": 64 * 2**20,
    "distributed.nanny.pre-spawn-environ.MALLOC_MMAP_THRESHOLD_": 16 * 2**20,
}


def _results(study, firsts, scheduler, progress):
    """Yield (first, state) of each chunk as it finishes; in order in this process."""
    if scheduler is None:
        for first in firsts:
            yield first, study.chunk_state(first, progress)
    elif scheduler == "processes":
        from distributed import Client, LocalCluster

        import dask

        with dask.config.set(WORKER_MALLOC), LocalCluster(
                n_workers=os.cpu_count() or 1, threads_per_worker=1, processes=True, host="127.0.0.1",
                dashboard_address=None) as cluster, Client(cluster) as client:
            yield from _stream(study, firsts, client)
    else:
        yield from _stream(study, firsts, scheduler)


def _stream(study, firsts, client):
    """Chunks on a dask cluster, at most two per worker thread in flight, yielded as they finish.

    A bounded window keeps memory flat on the workers and here however many
    chunks a study has; a chunk lost with its worker is recomputed by dask.
    """
    from distributed import as_completed

    pending = iter(firsts)
    window = 2 * max(1, sum(client.nthreads().values()))
    futures = as_completed([client.submit(_chunk_task, study, first, pure=False)
                            for first in itertools.islice(pending, window)], with_results=True)
    for future, result in futures:
        yield result
        future.release()
        for first in itertools.islice(pending, 1):
            futures.add(client.submit(_chunk_task, study, first, pure=False))


def _fingerprint(study):
    return json.dumps({"study": study.parameters(), "version": __version__}, sort_keys=True)


#: Engines per step of the mechanical chain when it runs to a target error.
MECHANICS_BATCH = 25


def _cycles(engine, parts, assembly, fit, rows, crank_angle, crank_method, film_method):
    """Bearing loads, film and life over the cycle of the engines ``rows`` (a slice) of a chunk."""
    count = rows.stop - rows.start
    built = np.all(assembly.status[rows] == ASSEMBLED, axis=1)
    out = {k: np.full((count, engine.main_bearings), np.nan) for k in MECHANICS_FIELDS}
    out["load_history"] = np.full((count, engine.main_bearings, crank_angle.size, 2), np.nan)
    out["h_min_history"] = np.full((count, engine.main_bearings, crank_angle.size), np.nan)
    status = np.full(count, NOT_COMPUTED, np.int8)
    if built.any():
        clearance = fit["clearance_operating"][rows][built]
        r = engine_cycles(engine.crank, bore_offset=parts.bore_offset[rows][built],
                          journal_eccentricity=parts.journal_eccentricity[rows][built],
                          clearance=clearance, crank_angle=crank_angle, method=crank_method)
        out["reaction_max"][built] = np.linalg.norm(r.reactions, axis=-1).max(axis=1)
        status[built] = worst_status(r.status)
        films = bearing_films(engine.crank, r.reactions, crank_angle, clearance=clearance,
                              journal_d=parts.journal_d[rows][built], steady_method=film_method)
        for name in ("h_min", "h_min_mean", "alpha", "life", "temperature"):
            out["film_temperature" if name == "temperature" else name][built] = getattr(films, name)
        out["load_history"][built] = np.moveaxis(r.reactions, 1, 2)
        out["h_min_history"][built] = films.history
    return out, status


#: Per-bearing results of the mechanical chain stored in a dataset.
MECHANICS_FIELDS = ("reaction_max", "h_min", "h_min_mean", "alpha", "life", "film_temperature")


def _no_bar(progress):
    return None if progress is None else not progress


def _union_labels(schemes):
    labels = []
    for s in schemes:
        for lab in s.shell.labels:
            if lab not in labels:
                labels.append(lab)
    return sorted(labels, key=lambda x: (x != "-", x))


def _concat_parts(parts):
    from .parts import BlockParts

    return BlockParts(*(np.concatenate([getattr(p, f) for p in parts]) for f in BlockParts.__dataclass_fields__))


class _Output:
    """Preallocated arrays of a study, filled chunk by chunk."""

    def __init__(self, n_schemes, n, b, n_labels, history_engines, n_angles):
        shape = (n_schemes, n, b)
        hist = (n_schemes, history_engines, b, n_angles)
        self.history = {"load_history": np.full((*hist, 2), np.nan), "h_min_history": np.full(hist, np.nan)}
        self.parts = {k: np.empty((n, b)) for k in ("housing_bore", "housing_reading", "journal_d", "journal_reading")}
        self.block_scrapped = np.empty(n, bool)
        self.crank_scrapped = np.empty(n, bool)
        self.grades = {k: np.empty(shape, "<U2") for k in ("housing_grade", "journal_grade", "shell_upper_grade", "shell_lower_grade")}
        self.floats = {k: np.empty(shape) for k in ("shell_upper_wall", "shell_lower_wall", "shell_upper_crush",
                                                    "shell_lower_crush", "clearance_nominal", *FIT_FIELDS)}
        self.loss_of_fit = np.empty(shape, bool)
        self.mechanics = {k: np.full(shape, np.nan) for k in MECHANICS_FIELDS}
        self.crank_status = np.full((n_schemes, n), NOT_COMPUTED, np.int8)
        self.offsets = {k: np.empty((n, b, 2)) for k in ("bore_offset", "journal_eccentricity")}
        self.mechanics_next = 0  # first engine the mechanical chain has not run on
        self.mechanics_done = False
        self.origin = 0  # study number of engine 0 here
        self.h_min_before = None  # cycle-minimum film of the engines before origin (target_error)
        self.status = np.empty(shape, np.int8)
        self.option = np.empty(shape, np.int8)
        self.made = np.zeros((n_schemes, n_labels), np.int64)
        self.used = np.zeros((n_schemes, n_labels), np.int64)
        self.left = np.zeros((n_schemes, n_labels), np.int64)
        self.scrapped = np.zeros(n_schemes, np.int64)

    def _per_engine(self):
        """Every per-engine array, by name, with its engine axis."""
        arrays = {f"parts.{k}": (v, 0) for k, v in self.parts.items()}
        arrays.update({f"offsets.{k}": (v, 0) for k, v in self.offsets.items()})
        arrays.update({"block_scrapped": (self.block_scrapped, 0), "crank_scrapped": (self.crank_scrapped, 0)})
        arrays.update({f"grades.{k}": (v, 1) for k, v in self.grades.items()})
        arrays.update({f"floats.{k}": (v, 1) for k, v in self.floats.items()})
        arrays.update({f"mechanics.{k}": (v, 1) for k, v in self.mechanics.items()})
        arrays.update({f"history.{k}": (v, 1) for k, v in self.history.items()})
        arrays.update({"status": (self.status, 1), "option": (self.option, 1), "loss_of_fit": (self.loss_of_fit, 1),
                       "crank_status": (self.crank_status, 1)})
        return arrays

    def film_error(self, engines):
        """Largest relative 95 % half-width over schemes of the mean cycle-minimum film of the first engines."""
        worst = 0.0
        h_min = self.mechanics["h_min"][:, :engines - self.origin]
        if self.h_min_before is not None:
            h_min = np.concatenate([self.h_min_before, h_min], axis=1)
        for h in h_min:
            computed = np.isfinite(h).any(axis=1)  # engines the chain ran on
            values = np.nanmean(h[computed], axis=1)
            if values.size < 2:
                return np.inf
            worst = max(worst, 1.96 * values.std(ddof=1) / np.sqrt(values.size) / values.mean())
        return worst

    def counters(self):
        return {k: getattr(self, k).copy() for k in ("made", "used", "left", "scrapped")}

    def chunk_state(self, engines, before):
        """The chunk's slice of every array and its additions to the shell counters."""
        # plain slices: the history arrays hold only the first engines, so their slice may be shorter or empty
        state = {name: a[(slice(None),) * axis + (engines,)] for name, (a, axis) in self._per_engine().items()}
        state.update({f"count.{k}": getattr(self, k) - v for k, v in before.items()})
        state["mechanics.progress"] = np.array([self.mechanics_next, int(self.mechanics_done)])
        return state

    def load_chunk(self, engines, state):
        for name, (a, axis) in self._per_engine().items():
            index = (slice(None),) * axis + (engines,)
            a[index] = state[name]
        self.add_counts(state)

    def add_counts(self, state):
        for k in ("made", "used", "left", "scrapped"):
            getattr(self, k)[...] += state[f"count.{k}"]

    def store_parts(self, engines, parts):
        self.parts["housing_bore"][engines] = parts.housing_bore
        self.parts["housing_reading"][engines] = parts.housing_reading
        self.parts["journal_d"][engines] = parts.journal_d
        self.parts["journal_reading"][engines] = parts.journal_reading
        self.offsets["bore_offset"][engines] = parts.bore_offset
        self.offsets["journal_eccentricity"][engines] = parts.journal_eccentricity
        self.block_scrapped[engines] = parts.block_scrapped
        self.crank_scrapped[engines] = parts.crank_scrapped

    def store_assembly(self, i, engines, a, scheme, grade_labels):
        def labels(gradeset, index):
            return np.array((*gradeset.labels, ""))[index]

        self.grades["housing_grade"][i, engines] = labels(scheme.housing, a.housing_grade)
        self.grades["journal_grade"][i, engines] = labels(scheme.journal, a.journal_grade)
        self.grades["shell_upper_grade"][i, engines] = labels(scheme.shell, a.upper_grade)
        self.grades["shell_lower_grade"][i, engines] = labels(scheme.shell, a.lower_grade)
        self.floats["shell_upper_wall"][i, engines] = a.upper_wall
        self.floats["shell_lower_wall"][i, engines] = a.lower_wall
        self.floats["shell_upper_crush"][i, engines] = a.upper_crush
        self.floats["shell_lower_crush"][i, engines] = a.lower_crush
        self.floats["clearance_nominal"][i, engines] = a.clearance
        self.status[i, engines] = a.status
        self.option[i, engines] = a.option
        cols = [grade_labels.index(lab) for lab in scheme.shell.labels]
        self.made[i, cols] += a.shells_made
        self.used[i, cols] += a.shells_used
        self.left[i, cols] += a.shells_left
        self.scrapped[i] += a.shells_scrapped

    def store_fit(self, i, engines, fit):
        for name in FIT_FIELDS:
            self.floats[name][i, engines] = fit[name]
        self.loss_of_fit[i, engines] = fit["loss_of_fit"]

    def store_crank(self, i, first, crank):
        values, status = crank
        for name, v in values.items():
            if name in self.history:
                kept = self.history[name].shape[1]
                if first < kept:
                    self.history[name][i, first:min(first + status.size, kept)] = v[:kept - first]
            else:
                self.mechanics[name][i, first:first + status.size] = v
        self.crank_status[i, first:first + status.size] = status

    def dataset(self, study, engine, schemes, grade_labels, film_method, crank_angle):
        n, b = self.block_scrapped.size, engine.main_bearings
        sed = ("scheme", "engine", "bearing")
        ed = ("engine", "bearing")
        sg = ("scheme", "shell_grade")

        def var(dims, data, units, long_name, **attrs):
            return xr.Variable(dims, data, {"units": units, "long_name": long_name, **attrs})

        in_scheme = np.array([[lab in s.shell.labels for lab in grade_labels] for s in schemes])
        stated = np.array([s.stated_clearance if s.stated_clearance else (np.nan, np.nan) for s in schemes])
        data = {
            "housing_bore": var(ed, self.parts["housing_bore"], "m", "housing bore diameter (true)"),
            "housing_bore_reading": var(ed, self.parts["housing_reading"], "m", "housing bore diameter as read by the gauge"),
            "journal_d": var(ed, self.parts["journal_d"], "m", "journal diameter (true)"),
            "journal_d_reading": var(ed, self.parts["journal_reading"], "m", "journal diameter as read by the gauge"),
            "block_scrapped": var("engine", self.block_scrapped, "1", "block scrapped: a bore read outside its drawing limits"),
            "crank_scrapped": var("engine", self.crank_scrapped, "1", "crankshaft scrapped: a journal read outside its drawing limits"),
            "housing_grade": var(sed, self.grades["housing_grade"], "1", "housing bore grade (empty: not graded)"),
            "journal_grade": var(sed, self.grades["journal_grade"], "1", "journal grade (empty: not graded)"),
            "shell_upper_grade": var(sed, self.grades["shell_upper_grade"], "1", "upper shell grade fitted (empty: none)"),
            "shell_lower_grade": var(sed, self.grades["shell_lower_grade"], "1", "lower shell grade fitted (empty: none)"),
            "shell_upper_wall": var(sed, self.floats["shell_upper_wall"], "m", "upper shell crown wall thickness (true; NaN where status says none fitted)"),
            "shell_lower_wall": var(sed, self.floats["shell_lower_wall"], "m", "lower shell crown wall thickness (true; NaN where status says none fitted)"),
            "shell_upper_crush": var(sed, self.floats["shell_upper_crush"], "m", "crush height of the upper shell (NaN where none fitted)"),
            "shell_lower_crush": var(sed, self.floats["shell_lower_crush"], "m", "crush height of the lower shell (NaN where none fitted)"),
            "clearance_nominal": var(sed, self.floats["clearance_nominal"], "m",
                                     "nominal diametral clearance D_H - (s_upper + s_lower + D_J), no swell (NaN where status is not assembled)"),
            "contact_pressure": var(sed, self.floats["contact_pressure"], "Pa", "contact pressure between shell backs and housing bore in service"),
            "shell_stress": var(sed, self.floats["shell_stress"], "Pa", "mean compressive hoop stress of the shell wall in service (positive in compression)"),
            "housing_swell": var(sed, self.floats["housing_swell"], "m", "elastic growth of the housing bore diameter from the shell press fit"),
            "bore_in_service": var(sed, self.floats["bore_in_service"], "m", "housing bore diameter at operating temperature, swell included"),
            "clearance_operating": var(sed, self.floats["clearance_operating"], "m",
                                       "diametral operating clearance: press fit, swell and temperature (NaN where status is not assembled)"),
            "loss_of_fit": var(sed, self.loss_of_fit, "1", "the shells have no interference left at operating temperature"),
            "bore_offset": var(("engine", "bearing", "axis"), self.offsets["bore_offset"], "m",
                               "housing bore centre off the straight bearing line (coaxiality)"),
            "journal_eccentricity": var(("engine", "bearing", "axis"), self.offsets["journal_eccentricity"], "m",
                                        "main journal centre off the crankshaft axis at crank angle 0 (run-out)"),
            **{name: var(sed, self.mechanics[name], *summarise.MECHANICS_VARIABLES[name]) for name in MECHANICS_FIELDS},
            "crank_status": var(("scheme", "engine"), self.crank_status, "1", "status of the crankshaft beam stage",
                                flag_values=np.arange(len(CYCLE_STATUS), dtype=np.int8), flag_meanings=" ".join(CYCLE_STATUS)),
            "status": var(sed, self.status, "1", "assembly status of the bearing",
                          flag_values=np.arange(len(STATUS), dtype=np.int8), flag_meanings=" ".join(STATUS)),
            "shell_option": var(sed, self.option, "1", "shell pair used: 0 preferred, k > 0 the scheme's k-th alternative, -1 none"),
            "shells_made": var(sg, self.made, "1", "shells made and sorted into the grade"),
            "shells_used": var(sg, self.used, "1", "shells of the grade fitted to bearings"),
            "shells_left": var(sg, self.left, "1", "shells of the grade left in stock at the ends of the lots"),
            "shells_scrapped": var("scheme", self.scrapped, "1", "shells read outside every grade of the scheme (scrapped)"),
            "grade_in_scheme": var(sg, in_scheme, "1", "the scheme has this shell grade"),
            "clearance_stated": var(("scheme", "bound"), stated, "m", "clearance range stated by the scheme's source"),
            "clearance_limit": var(("scheme", "bound"), np.array([s.clearance_limits() for s in schemes]), "m",
                                   "worst-case nominal clearance over the scheme's allowed combinations"),
        }
        coords = {
            "scheme": ("scheme", [s.name for s in schemes], {"long_name": "selective-fitting scheme"}),
            "engine": ("engine", np.arange(n), {"long_name": "sampled engine (block, crankshaft and its shells)"}),
            "bearing": ("bearing", np.arange(1, b + 1), {"long_name": "main bearing position"}),
            "shell_grade": ("shell_grade", grade_labels, {"long_name": "shell grade label"}),
            "bound": ("bound", ["lower", "upper"], {"long_name": "interval bound"}),
            "axis": ("axis", ["cap", "transverse"], {"long_name": "engine-fixed axis: towards the bearing cap, transverse"}),
        }
        kept = self.history["h_min_history"].shape[1]
        if kept:
            hist = ("scheme", "sampled_engine", "bearing", "crank_angle")
            data["load_history"] = var((*hist, "axis"), self.history["load_history"], "N",
                                       "bearing load over the cycle (force of the journal on the bearing)")
            data["h_min_history"] = var(hist, self.history["h_min_history"], "m", "minimum oil film thickness over the cycle")
            coords["sampled_engine"] = ("sampled_engine", np.arange(kept),
                                        {"long_name": "engine of the mechanical chain (its number in the engine dimension)"})
            coords["crank_angle"] = ("crank_angle", crank_angle,
                                     {"units": "degree", "long_name": "crank angle from firing TDC of the first cylinder fired"})
        attrs = {
            "title": f"Selective assembly of {engine.title or engine.name}",
            "stackup_version": __version__,
            "study": json.dumps(study.parameters()),
            "seed": study.seed,
            "engine": engine.name,
            "engine_source": engine.source,
            "lot_engines": engine.shell_wall.lot_engines,
            "shell_surplus": engine.shell_wall.surplus,
            "shell_supply": engine.shell_wall.mode,
            "pilot_engines": study.pilot_engines,
            "film_method_used": film_method,
            "mechanics_engines_used": self.mechanics_next,
            "scheme_sources": json.dumps({s.name: s.source for s in schemes}),
            "press_fit": json.dumps(engine.press_fit.kwargs()),
            "clearance_window": list(engine.clearance_window),
            "life_target": engine.life_target,
            "crush_height_limits": [engine.shell_wall.crush.lo, engine.shell_wall.crush.hi],
            "Conventions": "CF-1.10",
        }
        return xr.Dataset(data, coords=coords, attrs=attrs)
