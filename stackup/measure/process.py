r"""A manufacturing process from its measurements: model, parameters, capability and shared share.

:func:`fit_process` fits the candidate models of :mod:`stackup.measure.models`
to the readings and chooses one; :func:`fit_csv` does the same for a column
of a CSV file, so every refusal names the file, the column and the line.

Methods
-------
*Choice.* Each candidate is fitted by maximum likelihood; the one with the
least Bayesian information criterion :math:`BIC = k\ln n - 2\ln L` is chosen.
BIC rather than AIC because the candidates nest (the normal is a skew-normal
of skewness 0, a mixture of equal components, a drift of slope 0): BIC is
consistent, choosing the true model with a probability that tends to one as
readings are added, where AIC keeps choosing a larger model than needed for a
share of samples however many there are; and a model the data do not ask for
is an assumption in the engine file. The measured share of right choices is
in ``reports/measured_data.md``.

*Goodness of fit.* The chosen model is tested by the Anderson-Darling
statistic of the readings' probability transforms with a parametric
bootstrap (:data:`GOF_RESAMPLES` samples simulated from the fitted model,
with its groups' shared share, and refitted), since the parameters were
estimated from the same data. A small p-value says the process is none of
the candidates: the result says so and the engine file entry is a guess.

*Gauge.* A gauge of repeatability :math:`R` adds independent normal noise
to every reading; the process is the fit with that noise removed
(:math:`\sigma_p^2 = \sigma^2 - R^2`, per model in :mod:`stackup.measure.models`).
Where :math:`R` is not below the readings' spread the fit is refused: the
gauge cannot see the process.

*Capability.* :math:`C_{pk}` is the quantile index of ISO 22514-2
(:math:`\min((U - X_{50})/(X_{99.865} - X_{50}), (X_{50} - L)/(X_{50} - X_{0.135}))`
with the quantiles of the fitted process), which is the classic
:math:`\min(U - \mu, \mu - L)/3\sigma` for a normal process. Its interval is
the percentile bootstrap: ``resamples`` resamples of the readings (of whole
groups when groups are given, since a block's bores are not independent),
each refitted with every candidate and its Cpk taken from the model the
resample itself chooses by BIC, so the interval carries the uncertainty of
the choice as well as of the parameters. That matters most for a skewed
process read as normal, where the tail quantile is the whole question; an
interval conditional on the chosen model (Bissell's approximation for a
normal, or the bootstrap of the chosen model alone) held the truth less
often in trials on skewed processes, and BCa did not do better (the trials:
``reports/measured_data.md``, Methods). The chosen model's parameters get percentile intervals from the
same resamples (Student's t and chi-square for a normal process without
groups).

*Shared share.* :mod:`stackup.measure.shared`.

References
----------
.. [1] Efron, B., Tibshirani, R. J., *An Introduction to the Bootstrap*, Chapman & Hall, 1993, ch. 13.
.. [2] ISO 22514-2:2017, Statistical methods in process management - Capability and performance - Part 2.
.. [3] Schwarz, G., Estimating the dimension of a model, *Annals of Statistics* 6 (1978) 461-464.
.. [4] Stephens, M. A., EDF statistics for goodness of fit, *JASA* 69 (1974) 730-737.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np
from scipy import stats

from .._random import as_generator
from .._validate import InRange, Integer, validated
from ..tolerances import CPK_QUANTILES
from . import _data
from .engine_file import inline
from .models import BY_NAME, MODELS, NormalModel
from .shared import group_codes, shared_share

#: Samples of the parametric bootstrap of the goodness-of-fit test.
GOF_RESAMPLES = 200
#: Below this p-value of the goodness-of-fit test the chosen model is said not to fit.
GOF_LEVEL = 0.05
#: Largest gauge repeatability accepted, in tolerance widths (more is a unit slip).
MAX_REPEATABILITY = 1.0


@dataclass(frozen=True)
class Estimate:
    """A fitted parameter with its interval; ``units`` "m" for lengths, "1" for shares and shapes."""

    value: float
    lo: float
    hi: float
    units: str


@dataclass(frozen=True)
class Candidate:
    """A candidate model's fit: reading parameters, log-likelihood, BIC; ``note`` says why it was left out."""

    model: str
    params: tuple
    loglik: float
    bic: float
    note: str = ""


@dataclass(frozen=True)
class GoodnessOfFit:
    """Anderson-Darling statistic of the chosen model, its parametric-bootstrap p-value and samples."""

    statistic: float
    p_value: float
    resamples: int


@dataclass(frozen=True)
class ProcessFit:
    """What :func:`fit_process` found; lengths in m.

    Attributes
    ----------
    model : str
        The chosen model ("normal", "skew-normal", "mixture", "drift").
    process : object
        The process as it is (gauge removed), a :mod:`stackup.tolerances` object.
    params : dict of str -> Estimate
        The process parameters with their intervals.
    cpk, cpk_ci : float, (float, float)
        Capability index (ISO 22514-2 quantile form) and its interval; ``cpk_method`` says how.
    shared, shared_ci : float or None, (float, float) or None
        Share of variance common to a group's parts (the engine file's ``shared``), given groups.
    candidates : tuple of Candidate
    goodness_of_fit : GoodnessOfFit
    notes : tuple of str
        What the reader must know (models left out, a failed goodness of fit, resamples dropped).
    """

    model: str
    process: object
    params: dict
    cpk: float
    cpk_ci: tuple
    cpk_method: str
    shared: float | None
    shared_ci: tuple | None
    candidates: tuple
    goodness_of_fit: GoodnessOfFit
    limits: tuple
    gauge_repeatability: float
    confidence: float
    notes: tuple
    source: str
    readings: np.ndarray = field(repr=False)
    reading_params: tuple = ()

    @property
    def n(self):
        return int(self.readings.size)

    def process_spec(self, units="mm"):
        """The engine file's ``process`` table as a dict, lengths in ``units``."""
        return BY_NAME[self.model].spec(np.array([e.value for e in self.params.values()]), _data.UNITS[units])

    def to_toml(self, units="mm"):
        """The engine file's ``process = {...}`` entry (and ``shared = ...`` given groups), lengths in ``units``.

        The lines go into the dimension's table of an engine file whose
        ``units`` is ``units``; a comment above them says where they come from.
        """
        lines = []
        for _, key, value, comment in self.entries("", units):
            lines += [f"# {line}" for line in comment.splitlines()]
            lines.append(f"{key} = {value if isinstance(value, str) else inline(value)}")
        return "\n".join(lines) + "\n"

    def entries(self, table, units="mm"):
        """The changes of :func:`stackup.measure.write_engine` that put this fit into ``[table]`` of an engine file.

        ``process`` (and ``shared``, given groups), lengths in ``units`` (the
        engine file's), each with a comment saying where it comes from.
        """
        lo, hi = self.cpk_ci
        where = f" of {self.source}" if self.source else ""
        gauge = (f"gauge repeatability {self.gauge_repeatability * 1e6:g} um removed" if self.gauge_repeatability
                 else "no gauge repeatability given (the process as read)")
        out = [(table, "process", inline(self.process_spec(units)),
                f"process fitted by stackup.measure from {self.n} readings{where}: {self.model} (least BIC), "
                f"{gauge};\nCpk {self.cpk:.2f} "
                f"({self.confidence:.0%} interval {lo:.2f}-{hi:.2f}, {self.cpk_method})")]
        if self.shared is not None:
            out.append((table, "shared", round(self.shared, 3),
                        f"shared fitted by stackup.measure (one-way ANOVA of normal scores): {self.confidence:.0%} "
                        f"interval {self.shared_ci[0]:.3f}-{self.shared_ci[1]:.3f}"))
        return out

    def table(self):
        """The candidates as a pandas DataFrame (log-likelihood, BIC, chosen, note)."""
        import pandas as pd

        return pd.DataFrame([{"model": c.model, "loglik": c.loglik, "bic": c.bic, "chosen": c.model == self.model,
                              "note": c.note} for c in self.candidates]).set_index("model")

    def summary(self, units="mm"):
        """A few lines of plain text: the model, its parameters, Cpk, shared share, fit test and notes."""
        scale, name = _data.UNITS[units], _data.UNIT_NAMES[units]
        out = [f"{self.source or 'values'}: {self.n} readings, limits {self.limits[0] / scale:g}-"
               f"{self.limits[1] / scale:g} {name}; model {self.model} (least BIC of "
               + ", ".join(f"{c.model} {c.bic:.1f}" for c in self.candidates if not c.note) + ")"]
        for key, e in self.params.items():
            k = scale if e.units == "m" else 1.0
            unit = f" {name}" if e.units == "m" else ""
            out.append(f"  {key} = {e.value / k:.6g}{unit} ({self.confidence:.0%} interval {e.lo / k:.6g}-"
                       f"{e.hi / k:.6g}{unit})")
        out.append(f"  Cpk = {self.cpk:.3f} ({self.confidence:.0%} interval {self.cpk_ci[0]:.3f}-{self.cpk_ci[1]:.3f}; "
                   f"{self.cpk_method})")
        if self.shared is not None:
            out.append(f"  shared = {self.shared:.3f} ({self.confidence:.0%} interval {self.shared_ci[0]:.3f}-"
                       f"{self.shared_ci[1]:.3f})")
        g = self.goodness_of_fit
        out.append(f"  goodness of fit: Anderson-Darling A2 = {g.statistic:.3f}, p = {g.p_value:.3f} "
                   f"({g.resamples} parametric-bootstrap samples)")
        out.extend(f"  note: {note}" for note in self.notes)
        return "\n".join(out)

    def figure(self, units="mm", *, label=None):
        """Histogram with the fitted densities and a normal probability plot (a matplotlib Figure)."""
        from .figures import process_figure

        return process_figure(self, units=units, label=label)


@validated(confidence=InRange(0.5, 1.0, lo_open=True, hi_open=True), resamples=Integer(minimum=100))
def fit_process(values, *, limits, gauge_repeatability=None, groups=None, sequence=None, confidence=0.95,
                resamples=1000, seed=0):
    """Fit a manufacturing process to measured readings of one dimension.

    Parameters
    ----------
    values : array_like
        Readings [m], one per part.
    limits : (float, float)
        Drawing limits [m], lower first.
    gauge_repeatability : float, optional
        Standard deviation of repeated readings of one part [m]; removed from the spread.
    groups : array_like, optional
        Group label of each reading (block, crankshaft): gives the shared share,
        and the bootstrap resamples whole groups.
    sequence : array_like, optional
        Order or time of manufacture of each reading: adds the drifting-mean
        (tool-wear) candidate.
    confidence : float
        Level of every interval.
    resamples : int
        Bootstrap resamples of the capability's and the parameters' intervals.
    seed : int or numpy.random.Generator
        Seed of the bootstrap samples (the result is reproducible).

    Returns
    -------
    ProcessFit

    Notes
    -----
    Methods in the module docstring of :mod:`stackup.measure.process`.
    """
    return _fit(values, limits=limits, gauge_repeatability=gauge_repeatability, groups=groups, sequence=sequence,
                confidence=confidence, resamples=resamples, seed=seed, where=_data.Where(), units="m")


@validated(confidence=InRange(0.5, 1.0, lo_open=True, hi_open=True), resamples=Integer(minimum=100))
def fit_csv(path, column, *, limits, units="mm", gauge_repeatability=None, group=None, sequence=None,
            drop_missing=False, confidence=0.95, resamples=1000, seed=0):
    """:func:`fit_process` on a column of a CSV file; ``limits`` and ``gauge_repeatability`` in ``units``.

    ``group`` and ``sequence`` name the columns of the group labels and the
    manufacturing order. Rows with an empty or NaN cell are refused, or with
    ``drop_missing`` left out and counted in the result's notes.
    """
    if units not in _data.UNITS:
        raise ValueError(f"units: {units!r} is not one of {', '.join(map(repr, _data.UNITS))}")
    scale = _data.UNITS[units]
    numeric = [column] + ([sequence] if sequence else [])
    table = _data.read_csv(path, numeric=numeric, text=[group] if group else [], drop_missing=drop_missing)
    lo, hi = _data.drawing_limits(limits, field="limits", units=_data.UNIT_NAMES[units])
    _data.tolerance_in_units(lo, hi, units)
    r = None if gauge_repeatability is None else _length("gauge_repeatability", gauge_repeatability) * scale
    fit = _fit(table.values[column] * scale, limits=(lo * scale, hi * scale), gauge_repeatability=r,
               groups=table.values[group] if group else None, sequence=table.values[sequence] if sequence else None,
               confidence=confidence, resamples=resamples, seed=seed, where=table.where(column), units=units)
    if table.dropped:
        shown = ", ".join(map(str, table.dropped_lines[:5])) + (" ..." if table.dropped > 5 else "")
        note = f"{table.dropped} rows with an empty or NaN cell left out (lines {shown})"
        fit = replace(fit, notes=(note, *fit.notes))
    return fit


def _length(name, value):
    v = float(value)
    if not np.isfinite(v) or v < 0:
        raise ValueError(f"{name}: {value!r} is not valid; must be a finite length >= 0")
    return v


def _fit(values, *, limits, gauge_repeatability, groups, sequence, confidence, resamples, seed, where, units):
    x = _data.finite_values(values, where)
    lo, hi = _data.drawing_limits(limits, field="limits", units=_data.UNIT_NAMES[units])
    scale = _data.UNITS[units]
    _data.plausible(x / scale, lo / scale, hi / scale, where, units)
    _data.enough(x / scale, where, needed=NormalModel.min_values, units=units,
                 model=f"a fit (the normal model; skew-normal {BY_NAME['skew-normal'].min_values}, "
                       f"mixture {BY_NAME['mixture'].min_values})")
    r = _repeatability(gauge_repeatability, x, lo, hi, where, scale, units)
    t = None if sequence is None else _sequence(sequence, x.size, where)
    codes = None if groups is None else _groups(groups, x.size, where)
    rng = as_generator(seed)
    candidates, notes = fit_candidates(x, t, r)
    chosen = min((c for c in candidates if not c.note), key=lambda c: c.bic)
    model = BY_NAME[chosen.model]
    p_read = np.array(chosen.params)
    p_proc = model.process_params(p_read, r)
    process = model.process(p_proc)
    gauge_factor = (process.std**2 + r * r) / process.std**2
    share = None if codes is None else shared_share(x, codes, gauge_factor=gauge_factor, confidence=confidence)
    cpk = float(quantile_cpk(model, p_proc, lo, hi))
    valid = [c for c in candidates if not c.note]
    cpk_ci, params, dropped = _bootstrap(model, valid, x, t, codes, r, lo, hi, confidence, resamples, rng)
    method = (f"percentile bootstrap of {resamples} resamples{' of whole groups' if codes is not None else ''}, the model "
              "chosen again in each")
    if dropped:
        notes.append(f"{dropped} of {resamples} bootstrap resamples dropped: with the gauge's repeatability removed "
                     "no candidate's process was valid (spread not above it)")
    if model.name == "normal" and codes is None:
        params = _normal_parameters(x, r, confidence)
    gof = _goodness_of_fit(model, x, t, codes, share, p_read, r, rng)
    if gof.p_value < GOF_LEVEL:
        notes.append(f"the {model.name} model fails the goodness-of-fit test (p = {gof.p_value:.3f}): the process "
                     "is none of the candidates; its engine file entry is an approximation")
    return ProcessFit(model.name, process, params, cpk, cpk_ci, method,
                      None if share is None else share.value, None if share is None else (share.lo, share.hi),
                      tuple(candidates), gof, (lo, hi), r, confidence, tuple(notes),
                      str(where) if where.file else "", x, tuple(p_read))


def _repeatability(value, x, lo, hi, where, scale, units):
    if value is None:
        return 0.0
    r = _length("gauge_repeatability", value)
    name = _data.UNIT_NAMES[units]
    if r > MAX_REPEATABILITY * (hi - lo):
        raise ValueError(f"gauge_repeatability: {r / scale:g} {name} is more than the tolerance width "
                         f"{(hi - lo) / scale:g} {name}; give it in the values' units ({name})")
    spread = float(np.std(x, ddof=1))
    if r >= spread:
        raise ValueError(f"{where}: the gauge's repeatability {r / scale:g} {name} is not below the readings' "
                         f"standard deviation {spread / scale:.3g} {name}, so the process spread "
                         "sigma_process^2 = sigma_read^2 - R^2 is not positive: the gauge cannot see this process "
                         f"(check R's units, {name}, or measure with a better gauge)")
    return r


def _sequence(sequence, n, where):
    t = _data.finite_values(sequence, where.sub("sequence"))
    if t.size != n:
        raise ValueError(f"sequence: {t.size} entries for {n} readings; give one per reading")
    span = t.max() - t.min()
    if span <= 0:
        raise ValueError(f"sequence: all {n} entries are equal; the drift needs the order or time of manufacture")
    return (t - t.min()) / span


def _groups(groups, n, where):
    g = np.asarray(groups)
    if g.ndim != 1 or g.size != n:
        raise ValueError(f"groups: {g.size} labels for {n} readings; give one group label per reading")
    return group_codes(g, f"{where} (groups)")


def fit_candidates(x, t, r):
    """Every candidate's fit; a note where one is left out (too few values, no sequence, gauge)."""
    out, notes = [], []
    for model in MODELS:
        if model.needs_sequence and t is None:
            continue
        if x.size < model.min_values:
            note = f"{x.size} readings; the {model.name} model needs at least {model.min_values}"
            out.append(Candidate(model.name, (), np.nan, np.nan, note))
            notes.append(note)
            continue
        p, ll = (v[0] for v in model.refit(x, t, repeatability=r))
        bic = model.n_params * np.log(x.size) - 2.0 * ll
        note = ""
        if np.any(np.isnan(model.process_params(p, r))):
            note = f"the gauge's repeatability is not below this model's spread; {model.name} left out"
            notes.append(note)
        out.append(Candidate(model.name, tuple(float(v) for v in p), float(ll), float(bic), note))
    return out, notes


def quantile_cpk(model, p, lo, hi):
    """ISO 22514-2 quantile capability index of ``model``'s process parameters ``p`` (..., k) over [lo, hi]."""
    q = model.ppf(CPK_QUANTILES, np.asarray(p, dtype=float))
    low, mid, high = q[..., 0], q[..., 1], q[..., 2]
    return np.minimum((hi - mid) / (high - mid), (mid - lo) / (mid - low))


def _normal_parameters(x, r, confidence):
    """Student's t interval of the mean and the chi-square interval of sigma (gauge removed): normal, no groups."""
    n = x.size
    s_read = float(np.std(x, ddof=1))
    t_half = stats.t.ppf(0.5 + confidence / 2, n - 1) * s_read / np.sqrt(n)
    chi = stats.chi2.ppf([0.5 + confidence / 2, 0.5 - confidence / 2], n - 1)
    var_lo, var_hi = (n - 1) * s_read**2 / chi - r * r
    mean = float(x.mean())
    return {"mean": Estimate(mean, mean - t_half, mean + t_half, "m"),
            "sigma": Estimate(float(np.sqrt(s_read**2 - r * r)), float(np.sqrt(max(var_lo, 0.0))),
                              float(np.sqrt(var_hi)), "m")}


def _resample(x, t, codes, resamples, rng):
    """Bootstrap index rows (padded) and their mask: values, or whole groups when ``codes`` are given."""
    if codes is None:
        idx = rng.integers(0, x.size, size=(resamples, x.size))
        return idx, np.ones(idx.shape, bool)
    members = [np.flatnonzero(codes == g) for g in range(codes.max() + 1)]
    picks = rng.integers(0, len(members), size=(resamples, len(members)))
    rows = [np.concatenate([members[g] for g in row]) for row in picks]
    width = max(len(r) for r in rows)
    idx = np.zeros((resamples, width), int)
    mask = np.zeros((resamples, width), bool)
    for k, row in enumerate(rows):
        idx[k, :row.size], mask[k, :row.size] = row, True
    return idx, mask


def _select(candidates, x, t, mask, r, lo, hi):
    """Each row refitted with every candidate (started from its fit to the data): the least-BIC one's Cpk.

    Returns the Cpk of each row (NaN where no candidate's process is valid)
    and each candidate's process parameters per row.
    """
    n = mask.sum(axis=1)
    best = np.full(x.shape[0], np.inf)
    cpk = np.full(x.shape[0], np.nan)
    fits = {}
    for cand in candidates:
        model = BY_NAME[cand.model]
        p, ll = model.refit(x, t, mask, start=np.array(cand.params), repeatability=r)
        proc = model.process_params(p, r)
        ok = np.all(np.isfinite(proc), axis=1)
        bic = np.where(ok, model.n_params * np.log(n) - 2.0 * ll, np.inf)
        value = np.full(x.shape[0], np.nan)
        value[ok] = quantile_cpk(model, proc[ok], lo, hi)
        better = bic < best
        cpk, best = np.where(better, value, cpk), np.where(better, bic, best)
        fits[cand.model] = proc
    return cpk, fits


def _bootstrap(model, candidates, x, t, codes, r, lo, hi, confidence, resamples, rng):
    """Percentile intervals of Cpk (the model chosen again in every resample) and of the chosen model's parameters."""
    idx, mask = _resample(x, t, codes, resamples, rng)
    cpk, fits = _select(candidates, x[idx], None if t is None else t[idx], mask, r, lo, hi)
    point = model.process_params(np.array(next(c for c in candidates if c.model == model.name).params), r)
    boot = np.column_stack([cpk, fits[model.name]])
    boot = boot[np.all(np.isfinite(boot), axis=1)]
    tail = 50.0 * (1.0 - confidence)
    ends = np.percentile(boot, [tail, 100.0 - tail], axis=0).T
    params = {name: Estimate(float(point[k]), float(ends[k + 1, 0]), float(ends[k + 1, 1]),
                             "m" if model.lengths[k] else "1") for k, name in enumerate(model.parameters)}
    return (float(ends[0, 0]), float(ends[0, 1])), params, resamples - boot.shape[0]


def anderson_darling(u):
    """Anderson-Darling statistic of probability transforms ``u`` (rows), which are uniform under the model."""
    u = np.clip(np.sort(u, axis=-1), 1e-300, 1.0 - 1e-16)
    n = u.shape[-1]
    i = np.arange(1, n + 1)
    return -n - np.mean((2 * i - 1) * (np.log(u) + np.log1p(-u[..., ::-1])), axis=-1)


def _goodness_of_fit(model, x, t, codes, share, p_read, r, rng):
    """Anderson-Darling test of the chosen model, its p-value by parametric bootstrap (groups kept)."""
    observed = float(anderson_darling(model.conditional_cdf(x, t, p_read)))
    z = rng.standard_normal((GOF_RESAMPLES, x.size))
    if codes is not None and share is not None and model.name != "drift":
        rho = share.readings_share
        z = np.sqrt(rho) * rng.standard_normal((GOF_RESAMPLES, codes.max() + 1))[:, codes] + np.sqrt(1 - rho) * z
    if model.name == "drift":
        sim = p_read[0] + (p_read[1] - p_read[0]) * t + p_read[2] * z
    else:
        sim = model.process(p_read).from_normal(z)
    tt = None if t is None else np.broadcast_to(t, sim.shape)
    p_sim = model.refit(sim, tt, None, start=p_read, repeatability=r)[0]
    stat = anderson_darling(model.conditional_cdf(sim, tt, p_sim))
    return GoodnessOfFit(observed, float((1 + np.sum(stat >= observed)) / (1 + GOF_RESAMPLES)), GOF_RESAMPLES)
