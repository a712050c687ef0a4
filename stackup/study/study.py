"""The :class:`Study`: its parameters, checked once when it is made, and its run into one dataset.

A study is plain data (engine, schemes, size, seed, the tier of each stage);
:meth:`Study.run` hands its chunks to a scheduler
(:mod:`~stackup.study.schedule`), each chunk to the chain
(:mod:`~stackup.study.chain`), and the results to a sink
(:mod:`~stackup.study.sinks`).
"""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass

import xarray as xr
from tqdm.auto import tqdm

from .._validate import InRange, Integer, OneOf, OrNone, Window
from .._random import seed_sequence
from ..crank.cycle import METHODS as CRANK_METHODS
from ..fit import METHODS as FIT_METHODS
from ..film.cycle import canonical_tier
from ..film.registry import Names as FilmTiers
from ..life import FILM_STATISTICS
from ..parts import SAMPLERS
from ..patterns import ISO_SCHEMES
from ..schemes import Scheme
from . import chain, inputs, summaries
from .context import context, fingerprint
from .failures import FailureCount
from .schedule import check_scheduler, results
from .sinks import sink
from .store import ChunkStore

#: Engines of the mechanical chain by default: enough for the main job's life B10 and cycle-minimum film P1 per
#: scheme, and the engine's life B10 (its weakest bearing), to be within +-5 % (95 %, engine bootstrap); the
#: errors against the number of engines are measured in reports/mechanics_sample_size.md.
MECHANICS_ENGINES = 300


@dataclass(frozen=True)
class _Float:
    """A constraint whose value a study keeps as a Python float (its parameters are plain data, stored as JSON)."""

    constraint: object

    def __call__(self, field, value):
        return float(self.constraint(field, value))


#: The checks of a study's parameters, by field, in the order they run when a study is made.
PARAMETERS = {
    "n_engines": Integer(minimum=1),
    "chunk_lots": Integer(minimum=1),
    "pilot_engines": Integer(minimum=1),
    "mechanics_engines": Integer(minimum=0),
    "target_error": OrNone(_Float(InRange(0.0, 1.0, lo_open=True))),
    "crank_angle_step": _Float(InRange(0.0, 90.0, lo_open=True)),
    "sampler": OneOf(SAMPLERS),
    "keep": OneOf(("everything", "summaries")),
    "fit_method": OneOf(FIT_METHODS),
    "crank_method": OneOf(CRANK_METHODS),
    "film_method": OneOf(FilmTiers(also=("auto",))),  # the registered film tiers, read at each check
    "bearing_law": OneOf(("paper", "fitted")),
    "tilt_method": OneOf(chain.TILT_METHODS),
    "film_error": _Float(InRange(0.0, 1.0)),
    "life_film": OneOf(FILM_STATISTICS),
    "film_check_engines": Integer(minimum=0),
    "failure_limit": _Float(InRange(0.0, 1.0)),
    "window": OrNone(Window()),
}


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
        Default :data:`MECHANICS_ENGINES`.
        Engines with a bearing not assembled are skipped and marked.
    keep : {"everything", "summaries"}
        Keep every engine, or only streaming summaries
        (:mod:`stackup.study.summaries`: histograms, counts, moments and extremes of
        the clearance and press-fit stages, shell counters, worst bearings,
        and the mechanical chain's results of the engines it runs on), so
        memory stays flat as ``n_engines`` grows. ``history`` is not kept
        with ``"summaries"``.
    history : bool
        Keep each mechanically computed engine's bearing loads and minimum
        film at every crank angle, on dimensions ``mech_engine`` and
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
        Film over the cycle on the engines of the crankshaft stage
        (:data:`stackup.film.cycle.FILM_METHODS`): quasi-static on a steady tier
        ("short", "finite", "reynolds"), or dynamic with the squeeze film
        ("mobility": short-bearing mobility orbit, "mobility-finite": the same
        with the finite-length correction, "reynolds-transient": the Reynolds
        reference, by far the slowest), or "auto" (default) for the cheapest
        dynamic tier whose measured cycle-minimum and cycle-mean film errors
        against the Reynolds reference are within ``film_error``
        (:func:`stackup.film.cycle.cheapest_film_method`).
    film_error : float
        Largest film error against the Reynolds reference that "auto" accepts
        [-] (worst over the built-in engines' main bearings of the
        cycle-minimum and the cycle-mean film,
        ``stackup/data/film_cycle_errors.toml``). Each tier's measured errors
        and cost, hence which tier the default admits, are in
        reports/film_speed_vs_error.md.
    bearing_law : {"paper", "fitted"}
        The crankshaft's bearing law: the engine's (the paper's constants, J
        scaled with each clearance; default), or J and dx fitted per engine and
        bearing to the steady film at its viscosity and clearance
        (:func:`stackup.study.chain.fitted_law`; a second crankshaft cycle per
        engine).
    tilt_method : {"equilibrium", "coupled", "free"}
        The journal's tilt in the film (:func:`stackup.study.chain.mechanical_chain`):
        each bearing's tilt balanced quasi-statically against the compliance
        at its own support, the crankshaft's in series with the block's
        (``supports.tilt_compliance``), rigid surfaces (default;
        :mod:`stackup.film.tilt`); the support moments of all bearings
        balanced with the crankshaft and the block over the cycle, the journal
        centre moved with the tilt, tilt squeeze and the elastic layer included
        (:mod:`stackup.film.coupled`; several times the chain's cost, not yet
        the default: reports/bench_chain.md); or the beam's slope held. With
        the first two ``h_min``, α and the lives read the film over the
        bearing surface (``h_min_midplane`` the mid-plane's); with the last the
        mid-plane film. The default's and the coupled march's errors against
        the transient reference: reports/coupled_supports.md.
    life_film : {"cycle-mean", "cycle-minimum"}
        The film Levanov's method 1 reads (:func:`stackup.life.cycle_film`):
        the cycle mean of the minimum film, as the paper's results imply, or
        the cycle minimum (a comparison: lives of hours for any bearing that
        touches boundary friction).
    film_check_engines : int
        Engines of each scheme (the first, up to ``mechanics_engines``) whose
        films run again with the mass-conserving tier
        (:func:`stackup.film.registry.check_tier`) at the same tilt and heat
        balance (``h_min_check``, ``h_min_mean_check``, ``life_check``): the
        report combines both tiers by control variates, so its film and life
        means carry the accurate tier's mean and the error of that estimate
        (multi-fidelity Monte Carlo); 0 skips it.
    progress : bool or None
        Show a progress bar; None shows one only on a terminal.
    sampler : {"mc", "qmc"}
        Pseudo-random Monte Carlo, or scrambled Sobol points for each
        engine's parts (randomised QMC, one scramble per lot).
    scenario : dict or None
        Disturbance of the engine's processes (:mod:`stackup.scenarios`), e.g.
        ``{"housing_shift": 1.0}`` for the bore mean one sigma up.
    failure_limit : float
        Largest share of engines or bearings a stage may fail on
        (:mod:`stackup.study.failures`: a scheme that grades no part, a
        crankshaft beam that does not converge) before the run stops with
        an error naming the stage and the likely cause [-]; 1.0 never stops.
    window : (float, float) or None
        Design window of the operating clearance [m] that the summaries
        count and the ranking uses; None takes the engine's.
    files : dict or None
        The texts of the input files, ``{"engine": {"name", "text",
        "extra"}, "schemes": {label: text}}`` (:mod:`stackup.study.inputs`);
        what it holds is used instead of the disk, the rest is read when the
        study is made (so a changed file does not change a study). Every
        dataset stores the full set (attribute ``input_files``), and
        :meth:`from_dataset` passes it here, so a rerun needs no file.
        Schemes given as :class:`~stackup.schemes.Scheme` objects (a
        designed scheme) are put here by their name.
    store : str or None
        Path of a Zarr store the results stream into as chunks finish
        (:mod:`stackup.study.store`), so a study larger than memory can keep every
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
    mechanics_engines: int = MECHANICS_ENGINES
    target_error: float | None = None
    history: bool = False
    keep: str = "everything"
    crank_angle_step: float = 1.0
    fit_method: str = "lame"
    crank_method: str = "bearing-law"
    film_method: str = "auto"
    film_error: float = 0.5
    bearing_law: str = "paper"
    tilt_method: str = "equilibrium"
    life_film: str = "cycle-mean"
    film_check_engines: int = 0
    progress: bool | None = None
    sampler: str = "mc"
    scenario: dict | None = None
    failure_limit: float = 0.05
    window: tuple | None = None
    files: dict | None = None
    store: str | None = None

    def __post_init__(self):
        self.film_method = canonical_tier(self.film_method, stacklevel=3)  # a deprecated name warns
        for name, constraint in PARAMETERS.items():
            setattr(self, name, constraint(name, getattr(self, name)))
        if (720.0 / self.crank_angle_step) % 1:
            raise ValueError(f"crank_angle_step: {self.crank_angle_step!r} deg does not divide 720 deg")
        given = {s.name: s.to_toml_text() for s in self.schemes if isinstance(s, Scheme)}
        self.schemes = tuple(s.name if isinstance(s, Scheme) else str(s) for s in self.schemes)
        if not self.schemes:
            raise ValueError("schemes: give at least one scheme")
        if len(set(self.schemes)) != len(self.schemes):
            raise ValueError(f"schemes: {list(self.schemes)!r} names a scheme twice")
        seed_sequence(self.seed)
        self.engine = str(self.engine)
        # the texts are read once, here: every chunk (and a worker without the files) uses these
        files = self.files or {}
        self.files = inputs.input_files(self.engine, self.schemes,
                                        {**files, "schemes": {**files.get("schemes", {}), **given}})

    def parameters(self):
        """The study's parameters as plain data (stored in the dataset's attrs)."""
        return {k: v for k, v in asdict(self).items() if k not in ("progress", "store", "files")}

    @classmethod
    def from_dataset(cls, ds, **changes):
        """The study that made ``ds``, reading its engine and schemes from the texts ``ds`` stores.

        ``Study.from_dataset(ds).run()`` gives ``ds`` again with no input file
        present; ``changes`` replace parameters (e.g. ``n_engines``).
        """
        if "study" not in ds.attrs or "input_files" not in ds.attrs:
            raise ValueError("ds: not a study dataset (attributes 'study' and 'input_files' missing)")
        params = json.loads(ds.attrs["study"])
        return cls(**{**params, "files": json.loads(ds.attrs["input_files"]), **changes})

    def chunk(self, first, progress=None):
        """Compute chunk ``first`` on its own (e.g. on a worker) for its sink.

        A :class:`~stackup.study.chain.ChunkResult`, or with ``keep="summaries"``
        its reduction to one summary per production lot
        (:class:`~stackup.study.summaries.ChunkSummary`). ``progress`` is the
        mechanical chain's progress over the chunks before, which only a
        ``target_error`` study needs (in order).
        """
        ctx = context(self)
        result = chain.run_chunk(ctx, self, first, progress)
        failed = FailureCount.of_chunk(result)
        if self.keep == "summaries":
            result = summaries.reduce_chunk(result, lot_engines=ctx.lot, window=ctx.engine.clearance_window,
                                            limits=ctx.engine.press_fit_limits,
                                            minimum_clearance=ctx.engine.minimum_clearance)
        result.failures = failed
        return result

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
        ctx = context(self)
        check_scheduler(scheduler, self)
        store = ChunkStore(self.store, fingerprint(self)) if self.store is not None else None
        out = sink(self, ctx, store)
        firsts = list(range(0, ctx.n_lots, self.chunk_lots))
        with tqdm(total=len(firsts), unit="chunk", disable=None if self.progress is None else not self.progress,
                  desc="study") as bar:
            finished = out.resume()
            bar.update(len(finished))
            todo = [first for first in firsts if first not in finished]
            failures = FailureCount()
            for result in results(self, todo, scheduler, out.progress):
                failures.merge(result.failures).check(self.failure_limit)  # stop before storing a failed chunk
                out.add(result)
                bar.update(1)
        return out.result()
