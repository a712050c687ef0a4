"""Where the stages meet: one chunk of production lots through every stage of a study.

    parts -> assembly (per scheme) -> press fit -> crankshaft -> film -> life

Each stage is called through its public API with plain arrays; no stage
imports another. The result of a chunk is a :class:`ChunkResult`: the
chunk's per-engine variables under their dataset names
(:data:`stackup.study.schema.PER_ENGINE`), the shell counters and the
mechanical chain's progress.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from ..assembly import ASSEMBLED, assemble
from ..crank import support_compliance, support_slopes
from ..crank.cycle import engine_cycles, worst_status
from ..crank.law import BellakhdharLaw, fit_bellakhdhar
from ..film.bearing_law import load_displacement
from ..film.coupled import STATES as TILT_STATES
from ..film.coupled import ElasticLayer, support_moments
from ..film.cycle import FILM_STATUS, HEAT_STEP, at_wall, bearing_films, checked_film, wall_film
from ..film.heat import heat_balance
from ..film.journal import vector_length
from ..film.registry import tier as film_tier
from .. import _validate as check
from .. import materials
from ..contact import column_stiffness, composite_roughness, contact_modulus
from ..life import alpha as boundary_share
from ..life import cycle_film, levanov_method1, levanov_method2
from ..parts import BlockParts, draw_lot
from ..stats import mean_half_width
from .._random import lot_generator
from . import schema
from .clearance import operating_clearance, press_fit_checks, soaked_clearances

#: Engines per step of the mechanical chain when it runs to a target error.
MECHANICS_BATCH = 25
#: The journal's tilt in the film: the support moments of every bearing balanced with the crankshaft and the block
#: over the cycle (:mod:`stackup.film.coupled`), each bearing's tilt balanced against the film's moment alone
#: (:mod:`stackup.film.tilt`, a rigid block), or the beam's slope held (upper bound).
TILT_METHODS = ("equilibrium", "coupled", "free")


@dataclass
class ShellCounts:
    """Shell counters of some lots, per scheme: made, used and left per grade, scrapped."""

    made: np.ndarray  # (schemes, grades)
    used: np.ndarray
    left: np.ndarray
    scrapped: np.ndarray  # (schemes,)

    @classmethod
    def zeros(cls, n_schemes, n_grades):
        return cls(*(np.zeros((n_schemes, n_grades), np.int64) for _ in range(3)), np.zeros(n_schemes, np.int64))

    def add(self, other):
        """Add ``other``'s counts to these, in place."""
        for name in ("made", "used", "left", "scrapped"):
            getattr(self, name)[...] += getattr(other, name)


@dataclass
class MechanicsProgress:
    """How far the mechanical chain has run: engines ``[0, next)`` are done; ``done`` once it stops."""

    next: int = 0
    done: bool = False


@dataclass
class ChunkResult:
    """What one chunk of production lots computed.

    Attributes
    ----------
    first : int
        First lot of the chunk (its number in the study's chunking).
    engines : range
        Study numbers of the chunk's engines.
    per_engine : dict of str -> numpy.ndarray
        Every variable of :data:`schema.PER_ENGINE`, the chunk's engines on
        the variable's engine axis.
    per_mech : dict of str -> numpy.ndarray
        The :data:`schema.MECHANICS` variables (and :data:`schema.HISTORY`
        with ``Study(history=True)``) of the chunk's engines within the
        mechanical range (the study's first engines), on ``mech_engine``;
        engines the chain did not reach are ``not_computed``.
    shells : ShellCounts
    progress : MechanicsProgress
        The mechanical chain's progress after this chunk.
    """

    first: int
    engines: range
    per_engine: dict
    per_mech: dict
    shells: ShellCounts
    progress: MechanicsProgress
    failures: object = None  # the chunk's FailureCount, set by Study.chunk

    @property
    def h_min_head(self):
        """Cycle-minimum film of the chunk's engines within the mechanical range (schemes, engines, bearings)."""
        return self.per_mech["h_min"]

    def take(self, rows):
        """The per-engine variables of the chunk's engines ``rows`` (a slice), by name."""
        return {name: value[(slice(None),) * schema.PER_ENGINE[name].engine_axis + (rows,)]
                for name, value in self.per_engine.items()}


def run_chunk(ctx, study, first, progress=None):
    """Compute chunk ``first`` (lots ``first`` .. ``first + chunk_lots - 1``) through every stage.

    Parameters
    ----------
    ctx : stackup.study.context.Context
        What follows from the study's parameters alone (engine, schemes, shell aims, ...).
    study : stackup.study.Study
        Stage options: tiers, sampler, ``history``, ``target_error``.
    first : int
        First lot of the chunk.
    progress : MechanicsProgress and h_min of earlier engines, optional
        A ``target_error`` study's progress over the chunks before, in order
        (``(MechanicsProgress, h_min_before)``); None for every other study.
    """
    lots, e0, e1 = ctx.bounds(first, study.chunk_lots)
    sizes = {"scheme": len(ctx.schemes), "engine": e1 - e0, "bearing": ctx.engine.main_bearings, "axis": 2}
    # the stages skip their input checks here: the engine and schemes were checked when read, the study's
    # parameters when it was made, and every array comes from a stage
    with check.trusted():
        drawn = [draw_lot(ctx.engine, lot_generator(ctx.root, k), min(ctx.lot, study.n_engines - k * ctx.lot),
                          study.sampler) for k in lots]
        parts = BlockParts(*(np.concatenate([getattr(p, f) for p, _ in drawn])
                             for f in BlockParts.__dataclass_fields__))
        out, shells, stages = _assembly_and_fit(ctx, study, parts, drawn, sizes)
        mech, state = _mechanical_range(ctx, study, parts, stages, (e0, e1), sizes, progress)
    return ChunkResult(first, range(e0, e1), out, mech, shells, state)


def _assembly_and_fit(ctx, study, parts, drawn, sizes):
    """Every scheme's assembly and press fit of a chunk's ``parts``.

    Returns the chunk's :data:`schema.PER_ENGINE` variables, its shell
    counters and each scheme's (assembly, press fit) for the mechanical chain.
    """
    out = {name: var.empty(sizes) for name, var in schema.PER_ENGINE.items()}
    out.update(housing_bore=parts.housing_bore, housing_bore_reading=parts.housing_reading,
               journal_d=parts.journal_d, journal_d_reading=parts.journal_reading,
               block_scrapped=parts.block_scrapped, crank_scrapped=parts.crank_scrapped,
               bore_offset=parts.bore_offset, journal_eccentricity=parts.journal_eccentricity)
    shells = ShellCounts.zeros(len(ctx.schemes), len(ctx.grade_labels))
    stages = []
    for i, (scheme, share) in enumerate(zip(ctx.schemes, ctx.shares)):
        made = [ctx.engine.shell_wall.make(scheme, normals, share) for _, normals in drawn]
        result = assemble(scheme, parts, made, lot_engines=ctx.lot)
        _record_assembly(out, shells, i, result, scheme, ctx.grade_labels)
        fit = _press_fit(ctx.engine, parts, result, study.fit_method)
        for name in schema.FIT:
            out[name][i] = fit[name]
        out["loss_of_fit"][i] = fit["loss_of_fit"]
        out["loss_of_fit_any_temperature"][i] = fit["loss_of_fit_any_temperature"]
        stages.append((result, fit))
    return out, shells, stages


def _mechanical_range(ctx, study, parts, stages, engines, sizes, progress):
    """The mechanical chain on the chunk's engines (``engines``: first and stop) within the mechanical range.

    Engines run in order, in batches at fixed engine numbers, until the target
    error is met, so the decisions do not depend on the chunking. Returns the
    :data:`schema.MECHANICS` (with ``history``, :data:`schema.PER_MECH`)
    variables and the progress after the chunk.
    """
    e0, e1 = engines
    mechanical = max(0, min(e1, ctx.mechanics) - e0)  # engines of the chunk in the mechanical range
    kept = schema.PER_MECH if study.history else schema.MECHANICS
    mech = {name: var.empty({**sizes, "mech_engine": mechanical, "crank_angle": ctx.crank_angle.size})
            for name, var in kept.items()}
    state, h_min_before = progress if progress is not None else (MechanicsProgress(min(e0, ctx.mechanics)), None)
    state = MechanicsProgress(state.next, state.done)
    a = max(e0, state.next)
    while not state.done and a < min(e1, ctx.mechanics):
        stop = min(e1, ctx.mechanics, (a // MECHANICS_BATCH + 1) * MECHANICS_BATCH)
        rows = slice(a - e0, stop - e0)
        for i, (result, fit) in enumerate(stages):
            checked = max(0, min(stop, study.film_check_engines) - a)  # the batch's first engines the check runs on
            for name, value in _mechanics(ctx, parts, result, fit, rows, study.crank_method, study.life_film,
                                          study.bearing_law, study.tilt_method, checked).items():
                if name in mech:
                    mech[name][i, rows] = value
        a = state.next = stop
        if a == ctx.mechanics or (study.target_error and a % MECHANICS_BATCH == 0
                                  and _film_error(mech["h_min"][:, :a - e0], h_min_before) <= study.target_error):
            state.done = True
    return mech, state


def _record_assembly(out, shells, i, a, scheme, grade_labels):
    """Scheme ``i``'s assembly into the chunk's arrays and shell counters."""
    def labels(gradeset, index):
        return np.array((*gradeset.labels, ""))[index]

    out["housing_grade"][i] = labels(scheme.housing, a.housing_grade)
    out["journal_grade"][i] = labels(scheme.journal, a.journal_grade)
    out["shell_upper_grade"][i] = labels(scheme.shell, a.upper_grade)
    out["shell_lower_grade"][i] = labels(scheme.shell, a.lower_grade)
    out["shell_upper_wall"][i] = a.upper_wall
    out["shell_lower_wall"][i] = a.lower_wall
    out["shell_upper_crush"][i] = a.upper_crush
    out["shell_lower_crush"][i] = a.lower_crush
    out["clearance_nominal"][i] = a.clearance
    out["status"][i] = a.status
    out["shell_option"][i] = a.option
    cols = [grade_labels.index(lab) for lab in scheme.shell.labels]
    shells.made[i, cols] += a.shells_made
    shells.used[i, cols] += a.shells_used
    shells.left[i, cols] += a.shells_left
    shells.scrapped[i] += a.shells_scrapped


#: Press-fit results stored per bearing: dataset name -> PressFit field.
FIT_FIELDS = {
    "contact_pressure": "contact_pressure",
    "shell_stress": "shell_stress",
    "housing_swell": "housing_swell",
    "clearance_operating": "clearance",
}
#: Press-fit checks over the declared temperatures: dataset name -> PressFitExtremes field.
EXTREME_FIELDS = {
    "contact_pressure_lowest": "lowest_contact_pressure",
    "shell_stress_highest": "highest_shell_stress",
}


#: The clearance with housing, shells and journal at one temperature: dataset name -> SoakedClearance field.
SOAKED_FIELDS = {"clearance_assembly": "assembly", "clearance_cold": "cold"}


@dataclass(frozen=True)
class SoakedClearance:
    """Diametral clearance at the assembly temperature and at the cold start [m]."""

    assembly: np.ndarray
    cold: np.ndarray


def _press_fit(engine, parts, assembly, method):
    """Press fit of the assembled bearings at the operating temperature and its checks over the declared ones.

    NaN (False) where a bearing is not assembled (the status says why).
    """
    ok = assembly.status == ASSEMBLED
    shells = dict(upper_wall=assembly.upper_wall[ok], lower_wall=assembly.lower_wall[ok],
                  upper_crush=assembly.upper_crush[ok], lower_crush=assembly.lower_crush[ok], method=method)
    fit = operating_clearance(engine, housing_bore=parts.housing_bore[ok], journal_d=parts.journal_d[ok], **shells)
    # the design checks over every declared temperature: the stress bites cold for a light-alloy housing,
    # the pressure hot (cold for cast iron)
    extremes = press_fit_checks(engine, housing_bore=parts.housing_bore[ok], **shells)
    soaked = SoakedClearance(*soaked_clearances(engine, housing_bore=parts.housing_bore[ok],
                                                journal_d=parts.journal_d[ok], **shells))
    out = {}
    for result, fields in ((fit, {**FIT_FIELDS, "loss_of_fit": "loss_of_fit"}),
                           (extremes, {**EXTREME_FIELDS, "loss_of_fit_any_temperature": "loss_of_fit"}),
                           (soaked, SOAKED_FIELDS)):
        for name, field in fields.items():
            value = getattr(result, field)
            full = np.zeros(ok.shape, bool) if value.dtype == bool else np.full(ok.shape, np.nan)
            full[ok] = value
            out[name] = full
    return out


def _mechanics(ctx, parts, assembly, fit, rows, crank_method, life_film, bearing_law="paper",
               tilt_method="equilibrium", checked=0):
    """Bearing loads, film and life over the cycle of the engines ``rows`` (a slice) of a chunk.

    Engines with a bearing not assembled are skipped (``not_computed``); the
    first ``checked`` engines of ``rows`` also run the check tier.
    Returns the :data:`schema.PER_MECH` variables of one scheme, engines first.
    """
    engine, crank_angle = ctx.engine, ctx.crank_angle
    count = rows.stop - rows.start
    built = np.all(assembly.status[rows] == ASSEMBLED, axis=1)
    sizes = {"scheme": 1, "mech_engine": count, "bearing": engine.main_bearings, "axis": 2,
             "crank_angle": crank_angle.size}
    out = {name: var.empty(sizes)[0] for name, var in schema.PER_MECH.items()}
    if built.any():
        values = mechanical_chain(engine, clearance=fit["clearance_operating"][rows][built],
                                  journal_d=parts.journal_d[rows][built], bore_offset=parts.bore_offset[rows][built],
                                  journal_eccentricity=parts.journal_eccentricity[rows][built],
                                  crank_angle=crank_angle, crank_method=crank_method, film_method=ctx.film_method,
                                  life_film=life_film, bearing_law=bearing_law, tilt_method=tilt_method,
                                  check_engines=int(np.count_nonzero(built[:checked])))
        for name, value in values.items():
            out[name][built] = value
    return out


def mechanical_chain(engine, *, clearance, journal_d, bore_offset, journal_eccentricity, crank_angle, crank_method,
                     film_method, life_film="cycle-mean", bearing_law="paper", tilt_method="equilibrium",
                     check_engines=0):
    """Crankshaft, oil film and life of assembled engines: the :data:`schema.PER_MECH` variables, engines first.

    Parameters
    ----------
    engine : Engine
        With a crank section.
    clearance, journal_d : array_like (engines, bearings)
        Diametral operating clearance and journal diameter [m].
    bore_offset, journal_eccentricity : array_like (engines, bearings, 2)
        Misalignment of the bores and journals [m].
    crank_angle : numpy.ndarray
        [deg]
    crank_method : str
        Tier of the crankshaft supports.
    film_method : str
        Film method of :func:`stackup.film.cycle.bearing_films` (quasi-static steady tier or dynamic tier).
    life_film : {"cycle-mean", "cycle-minimum"}
        The film statistic Levanov's method 1 reads (:func:`stackup.life.cycle_film`).
    bearing_law : {"paper", "fitted"}
        With ``crank_method="bearing-law"``: the engine's law (the paper's
        constants, J scaled with each clearance) or J and dx fitted per engine
        and bearing to the steady film (:func:`fitted_law`).
    tilt_method : {"equilibrium", "coupled", "free"}
        The journal's tilt in the film (:data:`TILT_METHODS`): ``coupled``, the
        support moments of all bearings balanced with the crankshaft (its
        rotational compliance between the supports) and the block (each
        support's angular compliance, the bulkhead's and the bore ring's,
        ``engine.crank.supports.tilt_compliance``) over the cycle,
        with the tilt's squeeze and the elastic layer under the film
        (:mod:`stackup.film.coupled`);
        ``equilibrium``, each bearing's tilt against the film's moment and the
        compliance at its own support (the crankshaft's there in series with
        the support's angular compliance, ``supports.tilt_compliance``: the
        moments of the other supports left out), marched with the tilt's
        squeeze on a dynamic film tier's orbit, held at each angle on a
        quasi-static one, rigid surfaces (:mod:`stackup.film.tilt`): with these two
        ``h_min``, α and the lives read the film over the bearing surface
        (:func:`_surface_film`), ``h_min_midplane`` the mid-plane's; or
        ``free``, the beam's slope held (its edges at the wall: a bound), where
        they read the mid-plane film.
    check_engines : int
        The first engines whose films run again with the check tier
        (:func:`stackup.film.cycle.checked_film`: ``h_min_check``,
        ``h_min_mean_check``, ``life_check``; NaN on the others).

    A bearing whose film is not a number (``film_status`` collapsed,
    not_periodic or failed; ``film_valid`` false) has NaN for every value
    that comes from the film (:data:`schema.FILM_NUMBERS`).
    """
    spec = engine.crank
    with check.trusted():  # the stages skip their input checks: every array comes from a stage or a checked input
        law, law_error = None, np.full(np.shape(clearance), np.nan)
        if bearing_law == "fitted" and crank_method == "bearing-law":
            law, law_error = fitted_law(engine, clearance=clearance, journal_d=journal_d, bore_offset=bore_offset,
                                        journal_eccentricity=journal_eccentricity, crank_angle=crank_angle)
        supports = spec.supports
        if supports is not None and supports.thermal_offset is not None:
            bore_offset = np.asarray(bore_offset) + supports.thermal_offset  # the block's heat bends the line
        r = engine_cycles(spec, bore_offset=bore_offset, journal_eccentricity=journal_eccentricity,
                          clearance=clearance, crank_angle=crank_angle, method=crank_method, law=law)
        # the journal's tilt against its bore: the beam's slope at the support (the misaligned bores and
        # journals bend the beam; the line-bored bores stay parallel to the line), turned back by the support
        # moments
        tilt = support_slopes(_pin_loads(spec, crank_angle)[None], r.displacements, spans=spec.spans, EI=spec.ei)
        constants = _engine_constants(engine)
        coupled = tilt_method == "coupled"
        films = bearing_films(spec, engine.oil_feed, r.reactions, crank_angle, clearance=clearance,
                              journal_d=journal_d, method=film_method, tilt=None if coupled else tilt,
                              tilt_compliance=constants.compliance if tilt_method == "equilibrium" else None)
        films, surface = _surface(films, tilt, constants, spec, crank_angle, clearance=clearance, journal_d=journal_d,
                                  film_method=film_method) if coupled else (films, None)
        film = _surface_film(films, surface, tilt_method)
        loads = np.moveaxis(r.reactions, 1, 2)
        out = {"reaction_max": np.hypot(r.reactions[..., 0], r.reactions[..., 1]).max(axis=1),
               "crank_status": worst_status(r.status),
               "tilt_free_max": vector_length(tilt).max(axis=1),
               "law_fit_error": law_error,
               "load_history": loads,
               **_film_values(films, surface, film, loads, crank_angle, engine.wear.critical_film, clearance),
               **_life_values(engine, films, surface, film, spec.bearing_width, clearance=clearance,
                              journal_d=journal_d,
                              crank_angle=crank_angle, life_film=life_film, roughness=constants.roughness,
                              modulus=constants.modulus),
               **_check_values(engine, films, film, r.reactions, crank_angle, clearance=clearance,
                               journal_d=journal_d, film_method=film_method, life_film=life_film,
                               engines=check_engines, coupled=coupled)}
    return _not_a_number(out, films.valid)


def _check_values(engine, films, film, reactions, crank_angle, *, clearance, journal_d, film_method, life_film,
                  engines, coupled):
    """The check tier's film and life on the first ``engines`` engines (NaN on the others).

    The check tier's error on the aligned journal's mid-plane film
    (:func:`stackup.film.cycle.checked_film`: the study's tier and the check
    tier at the same viscosity), as a share of the study tier's, taken off the
    study's mid-plane film and so off the film the study reads (over the
    surface where the support moments ran: the tilt's part of it is the
    geometry's, the centre's the tier's), per statistic (cycle minimum, cycle
    mean); with rigid surfaces (``coupled`` False) no cycle minimum below the
    wall's film (:func:`stackup.film.cycle.wall_film`), where the film tier holds an
    edge; a bearing where the check tier fails is NaN.
    """
    shape = np.shape(clearance)
    out = {name: np.full(shape, np.nan) for name in ("h_min_check", "h_min_mean_check", "life_check")}
    if engines == 0:
        return out
    first = slice(0, engines)
    cheap, accurate = checked_film(engine.crank, engine.oil_feed, reactions[first], crank_angle,
                                   viscosity=films.viscosity[first], clearance=np.asarray(clearance)[first],
                                   journal_d=np.asarray(journal_d)[first], method=film_method)
    mid = films.h_min[first]
    read = np.maximum(film, 0.0)[first]
    out["h_min_check"][first] = read.min(axis=-1) + mid.min(axis=-1) * (accurate.min(axis=-1) / cheap.min(axis=-1)
                                                                        - 1)
    if not coupled:  # an edge the tier holds at the wall stays there, whichever tier moves the centre
        out["h_min_check"][first] = np.maximum(out["h_min_check"][first], wall_film(np.asarray(clearance)[first]))
    mean = cycle_film(mid, statistic="cycle-mean")
    out["h_min_mean_check"][first] = cycle_film(read, statistic="cycle-mean") + mean * (
        cycle_film(accurate, statistic="cycle-mean") / cycle_film(cheap, statistic="cycle-mean") - 1)
    film = out["h_min_mean_check"] if life_film == "cycle-mean" else out["h_min_check"]
    wear = engine.wear
    out["life_check"][first] = levanov_method1(np.maximum(film[first], 0.0), h_lim_cr=wear.critical_film,
                                               wear_limit=wear.method1_wear_limit, wear_rate=wear.wear_rate).life
    return out


def _surface(films, tilt, constants, spec, crank_angle, *, clearance, journal_d, film_method):
    """The support moments over the cycle on the films' orbits (:func:`stackup.film.coupled.support_moments`), and
    the films with an engine whose surface film could not be computed (another bearing's orbit not a number)
    marked not valid, status failed."""
    surface = support_moments(films.position, np.moveaxis(tilt, 1, 2), crank_angle, compliance=constants.coupled,
                              journal_radius=np.asarray(journal_d) / 2, bearing_width=spec.bearing_width,
                              radial_clearance=np.asarray(clearance) / 2, viscosity=films.viscosity, speed=spec.speed,
                              layer=constants.layer, method=film_tier(film_method).length_model)
    lost = films.valid & ~np.isfinite(surface.film).all(axis=-1)
    if lost.any():
        films = replace(films, valid=films.valid & ~lost,
                        status=np.where(lost, FILM_STATUS.index("failed"), films.status).astype(np.int8))
    return films, surface


def _surface_film(films, surface, tilt_method):
    """The study's film over the cycle (engines, bearings, angles) [m], the one α and the lives read: over the
    bearing surface where the journal's tilt is turned back (the support moments' on the elastic layer,
    ``coupled``; the thinnest over the width with the rigid tilted journal, ``equilibrium``), the mid-plane's
    where the beam's slope is held (``free``: its edges at the wall, a bound, not a film)."""
    if surface is not None:
        return surface.film
    return films.h_min_edge if tilt_method == "equilibrium" else films.h_min


def _edge_contact(films, surface, loads, crank_angle, critical, clearance):
    """Share of the cycle with an edge in contact, the largest load and the thinnest film's angle there: with the
    support moments on the elastic layer an edge below ``critical`` (asperity contact), with rigid surfaces an
    edge held at the wall's film :math:`c(1 - \varepsilon_{lim})`."""
    if surface is None:
        edge = films.h_min_edge
        touching = at_wall(edge, clearance)
    else:
        edge = surface.film
        touching = (edge < critical) & (edge < films.h_min - 1e-9)
    load = np.where(touching, vector_length(loads), -np.inf).max(axis=-1)
    at = np.where(touching, edge, np.inf).argmin(axis=-1)
    angle = np.asarray(crank_angle, dtype=float)[at]
    some = touching.any(axis=-1)
    return touching.mean(axis=-1), np.where(some, load, np.nan), np.where(some, angle, np.nan)


def _film_values(films, surface, h, loads, crank_angle, critical, clearance):
    """The film's :data:`schema.PER_MECH` variables of a :func:`stackup.film.cycle.bearing_films` result, its
    support moments (``surface``, None with another tilt method) and the film the study reads (``h``,
    :func:`_surface_film`)."""
    edge = films.h_min_edge if surface is None else surface.film
    share, load, angle = _edge_contact(films, surface, loads, crank_angle, critical, clearance)
    tilt_status = np.full(films.h_min.shape[:-1], len(TILT_STATES), np.int8)
    unresolved = np.full(films.h_min.shape[:-1], np.nan)
    status = films.status
    if surface is not None:
        tilt_status, unresolved = surface.state, surface.unresolved
        # a periodic orbit with an edge in asperity contact somewhere in the cycle
        status = np.where((status == FILM_STATUS.index("periodic")) & (share > 0), FILM_STATUS.index("edge_contact"),
                          status).astype(np.int8)
    return {"h_min": h.min(axis=-1),
            "h_min_midplane": films.h_min.min(axis=-1),
            "h_min_edge": edge.min(axis=-1),
            "tilt_loss": films.h_min.min(axis=-1) - edge.min(axis=-1),
            "tilt_max": films.tilt_max if surface is None else vector_length(surface.tilt).max(axis=-1),
            "edge_contact_share": share,
            "edge_contact_load": load,
            "edge_contact_angle": angle,
            "tilt_status": tilt_status,
            "tilt_unresolved": unresolved,
            "p_max": films.p_max.max(axis=-1),
            "p_max_mean": films.p_max.mean(axis=-1),
            "film_status": status,
            "film_temperature": films.temperature,
            "friction_power": films.friction_power,
            "oil_flow": films.oil_flow,
            "feed_flow": films.feed_flow,
            "heat_status": films.heat_status,
            "film_valid": films.valid,
            "h_min_history": h}


def _life_values(engine, films, surface, film, bearing_width, *, clearance, journal_d, crank_angle, life_film,
                 roughness, modulus):
    """Life and wear of the bearings with these films: Levanov's method 1 on the film statistic ``life_film``,
    his wear chart (method 2) on the orbit; both, and α, on the film the study reads (``film``,
    :func:`_surface_film`; a negative one no film, 0)."""
    wear = engine.wear
    c = np.asarray(clearance) / 2
    h = np.maximum(film, 0.0)
    chart = levanov_method2(_wear_positions(films, surface, film, bearing_width, c), radial_clearance=c,
                            crank_angle=crank_angle, speed=engine.crank.speed,
                            journal_radius=np.asarray(journal_d) / 2, h_lim_cr=wear.critical_film,
                            roughness=roughness, contact_modulus=modulus, wear_limit=wear.wear_limit)
    h_min_mean = cycle_film(h, statistic="cycle-mean")
    life = levanov_method1(h_min_mean if life_film == "cycle-mean" else cycle_film(h, statistic=life_film),
                           h_lim_cr=wear.critical_film, wear_limit=wear.method1_wear_limit, wear_rate=wear.wear_rate)
    return {"h_min_mean": h_min_mean,
            "alpha": boundary_share(film, h_lim_cr=wear.critical_film),
            "life": life.life,
            "life_wear_chart": chart.life,
            "wear_rate": chart.wear_rate}


def _wear_positions(films, surface, film, bearing_width, radial_clearance):
    r"""Journal centres whose film around the bearing the wear chart reads (engines, bearings, angles, 2) [m].

    Where the study reads the mid-plane film, the mid-plane orbit. With the
    support moments the thinner edge's centre :math:`\mathbf x \pm \tfrac L2\boldsymbol\gamma`
    (:math:`\mathbf x` the centre the tilted film carries the load at); with the
    rigid tilted journal (``equilibrium``, whose tilt over the cycle the film
    tier does not keep) the mid-plane centre. Either moved along its direction
    so that its thinnest film is the film the study reads (``film``),
    :math:`c - |\mathbf x_e| = h`: the wear chart of Levanov's method 2 along the
    edge that carries the asperity contact (the contact zone's width across the
    bearing left out, as the paper's chart has none; with ``equilibrium`` the
    edge's turn from the mid-plane centre's direction too).
    """
    if film is films.h_min:
        return films.position
    if surface is None:
        edge = films.position
    else:
        half = 0.5 * bearing_width * surface.tilt
        plus, minus = surface.centre + half, surface.centre - half
        edge = np.where((vector_length(plus) >= vector_length(minus))[..., None], plus, minus)
    reach = vector_length(edge)
    target = np.asarray(radial_clearance)[..., None] - film
    scale = np.where(reach > 0, target / np.where(reach > 0, reach, 1.0), 0.0)
    return edge * scale[..., None]


def _not_a_number(values, valid):
    """``values`` with NaN for the film's numbers (:data:`schema.FILM_NUMBERS`) of bearings whose film is not valid.

    A collapsed film is the film held at the eccentricity limit and an orbit that did not close is not the
    bearing's periodic film: neither is a number a statistic or a ranking may read. ``film_status`` keeps
    the reason; the engine's life (its weakest bearing) becomes NaN with it.
    """
    lost = ~np.asarray(valid, bool)
    if not lost.any():
        return values
    out = dict(values)
    for name in schema.FILM_NUMBERS:
        v = np.asarray(out[name], dtype=float)
        out[name] = np.where(lost.reshape(lost.shape + (1,) * (v.ndim - lost.ndim)), np.nan, v)
    return out


#: Crank-pin loads of the last engines and grids the chain saw: (spec, crank angles, loads).
_PINS = []


def _pin_loads(spec, crank_angle):
    """``spec.pin_loads(crank_angle)``, kept for the next batch: every batch of a study asks for the same loads.

    The slider-crank and cylinder-pressure model is a large part of the crankshaft stage's cost on one engine
    (reports/bench_chain.md computes the loads once per batch).
    """
    for known, angle, loads in _PINS:
        if known is spec and np.array_equal(angle, crank_angle):
            return loads
    loads = spec.pin_loads(crank_angle)
    loads.setflags(write=False)
    _PINS[:] = [*_PINS[-3:], (spec, np.array(crank_angle, copy=True), loads)]
    return loads


@dataclass(frozen=True)
class EngineConstants:
    """What the chain reads of an engine for every batch: the compliance a journal's tilt meets at each support,
    the crankshaft's rotational compliance there plus the support's angular compliance (the bulkhead's and the
    bore ring's, ``supports.tilt_compliance``) (N+1, 2); ``coupled``, the crankshaft's between the supports
    plus each support's on the diagonal (2, N+1, N+1); the elastic layer under the film, and the wear's
    composite roughness and contact modulus."""

    compliance: np.ndarray
    coupled: np.ndarray
    layer: ElasticLayer
    roughness: float
    modulus: float


#: The engine constants of the last engines the chain saw: (engine, EngineConstants).
_CONSTANTS = []


def _engine_constants(engine):
    """The :class:`EngineConstants` of ``engine``, kept for the next batch (every batch asks for the same)."""
    for known, constants in _CONSTANTS:
        if known is engine:
            return constants
    spec, wear, fit = engine.crank, engine.wear, engine.press_fit
    journal, lining = materials.get(fit.journal_material), materials.get(wear.lining_material)
    compliance = support_compliance(spans=spec.spans, EI=spec.ei)
    coupled = support_compliance(spans=spec.spans, EI=spec.ei, coupled=True)
    if spec.supports is not None:  # the support turns with its film's moment, in series with the crankshaft
        compliance = compliance + spec.supports.tilt_compliance
        for c in range(2):
            coupled[c] += np.diag(spec.supports.tilt_compliance[:, c])
    for array in (compliance, coupled):
        array.setflags(write=False)
    roughness = float(composite_roughness(wear.journal_rq, wear.shell_rq))
    modulus = float(contact_modulus(journal.modulus, journal.poisson, lining.modulus, lining.poisson))
    constants = EngineConstants(compliance, coupled, ElasticLayer(layer_stiffness(engine), roughness, modulus),
                                roughness, modulus)
    _CONSTANTS[:] = [*_CONSTANTS[-3:], (engine, constants)]
    return constants


def layer_stiffness(engine):
    """Column stiffness of the shell under the film [Pa/m]: its lining and steel back
    (:func:`stackup.contact.column_stiffness`), the back's thickness the nominal wall less the lining."""
    fit = engine.press_fit
    wall = 0.5 * (engine.housing_bore.lo + engine.housing_bore.hi - engine.journal_d.lo - engine.journal_d.hi) / 2
    lining = materials.get(engine.wear.lining_material)
    back = materials.get(fit.shell_material)
    layers = [(fit.lining_thickness, lining)] if fit.lining_thickness > 0 else []
    layers.append((wall - fit.lining_thickness, back))
    return column_stiffness([t for t, _ in layers], [m.modulus for _, m in layers], [m.poisson for _, m in layers])


def fitted_law(engine, *, clearance, journal_d, bore_offset, journal_eccentricity, crank_angle):
    """The Bellakhdhar law with J and dx fitted per engine and bearing to the steady film.

    A first crankshaft cycle on the engine's law gives each bearing's loads, the
    quasi-static heat balance its effective viscosity; the law is then fitted
    (:func:`stackup.crank.law.fit_bellakhdhar`) to the finite tier's
    load-displacement curve (:func:`stackup.film.bearing_law.load_displacement`,
    up to 1.5 times the bearing's peak load) at the engine's speed, that
    viscosity and the bearing's clearance; stiffnesses and sigmoid stay the
    engine's. Returns (law with parameters (engines, 1, bearings), rms fit error
    (engines, bearings) [m]).
    """
    spec = engine.crank
    first = engine_cycles(spec, bore_offset=bore_offset, journal_eccentricity=journal_eccentricity,
                          clearance=clearance, crank_angle=crank_angle)
    loads = np.moveaxis(first.reactions, 1, 2)
    step = float(crank_angle[1] - crank_angle[0]) if len(crank_angle) > 1 else 720.0
    heat = heat_balance(loads[..., ::max(1, int(round(HEAT_STEP / step))), :], journal_d=journal_d,
                        bearing_width=spec.bearing_width, clearance=clearance, speed=spec.speed, oil=spec.oil,
                        supply_temperature=spec.oil_supply_temperature, feed=engine.oil_feed, method="finite")
    peak = np.linalg.norm(loads, axis=-1).max(axis=-1)
    load, displacement = load_displacement(max_load=1.5 * peak, journal_d=journal_d, bearing_width=spec.bearing_width,
                                           clearance=clearance, viscosity=heat.viscosity, speed=spec.speed)
    p = spec.law_parameters
    stiff = {k: p.get(k, getattr(BellakhdharLaw, k)) for k in ("k_lv", "k_hv", "theta0", "dtheta")}
    fit = fit_bellakhdhar(load, displacement, **stiff, radial_clearance=np.asarray(clearance) / 2)
    law = BellakhdharLaw(clearance=fit.law.clearance[:, None, :], dx=fit.law.dx[:, None, :], **stiff)
    return law, fit.rms_error


def _film_error(h_min, h_min_before):
    """Largest relative 95 % half-width over schemes of the mean cycle-minimum film of the engines so far.

    ``h_min`` (schemes, engines, bearings) of this chunk's engines so far,
    ``h_min_before`` those of the chunks before (or None).
    """
    worst = 0.0
    if h_min_before is not None:
        h_min = np.concatenate([h_min_before, h_min], axis=1)
    for h in h_min:
        computed = np.isfinite(h).any(axis=1)  # engines the chain ran on
        values = np.nanmean(h[computed], axis=1)
        if values.size < 2:
            return np.inf
        mean = abs(values.mean())  # the film over the surface can be negative (asperities pressed past)
        worst = max(worst, mean_half_width(values) / mean if mean > 0 else np.inf)
    return worst
