"""Facts of the mechanical chain: loads per position, film detail, film outcomes, heat balance, edge contact, life.

Each function reads a study dataset that keeps every engine of its
mechanical chain and returns plain numbers (SI units unless the name says
otherwise); where a stage did not run, or the dataset predates a variable,
it returns None.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np
import pandas as pd
from scipy import stats

from ..film.cycle import NOT_A_NUMBER
from ..film.orbit import ECCENTRICITY_LIMIT
from ..life import levanov_method1
from ..study.schema import flag
from .declared import FilmErrors, Wear
from .tables import bearing_summary, converged_engines, crank_summary, kept_summaries

#: Positions within this share of the range of loads (films) from the heaviest (thinnest) count among them.
POSITION_SHARE = 0.15


def _computed(ds):
    """Bearing-cycles whose film the chain computed, (schemes, engines, bearings)."""
    return ds.film_status.values != flag(ds.film_status, "not_computed")


@dataclass(frozen=True)
class EdgeContact:
    """Bearings whose journal edge touches its shell (``edge_contact``) among those whose film is a number.

    With rigid surfaces (``tilt_method`` equilibrium or free) an edge touches where the tilted journal's
    edge reaches the wall (its film held at the floor); with the support moments on the elastic layer
    (``coupled``) where the film over the surface falls below h_lim,cr at an edge.
    """

    computed: int                # bearing-cycles with a film that is a number
    touching: int                # of them, with the edge at the wall somewhere in the cycle
    per_scheme_pct: list         # share touching per scheme [%] (schemes with a computed film)
    per_position_share: list     # median share of the cycle at the wall per position, over those touching [-]
    floor: float                 # the film held at the wall, as a share of the radial clearance [-]
    surface: bool = False        # the film over the bearing surface ran (support moments, elastic layer)
    critical: float = np.nan     # h_lim,cr [m]
    per_position: pd.DataFrame = None  # touching bearings per position (where counted): their share [%], median
                                       # share of the cycle [-] and its 5-95 % over all the position's bearings
                                       # (the spread the tolerances and clearances give), thinnest film [m],
                                       # load [N] and crank angle [deg]
    periodic: float = np.nan     # share of the bearing-cycles whose support moments repeated within the march
    unresolved: tuple = (np.nan, np.nan)  # median and 95 % over the engines of the share of the march's solved
                                          # angles whose balance was not resolved to the tolerance
    counted: bool = True         # α and the lives read the film over the width, where the edges are (h_min below
                                 # h_min_midplane somewhere; a study that read the mid-plane has them equal)


def edge_contact(ds):
    """The :class:`EdgeContact` of a study, or None without the variables (a study before them, no film)."""
    if "edge_contact_share" not in ds or "film_status" not in ds:
        return None
    ran = _computed(ds) & ds.film_valid.values
    touching = ran & (ds.film_status.values == flag(ds.film_status, "edge_contact"))
    share = ds.edge_contact_share.values
    per_position = [float(np.nanmedian(share[..., b][touching[..., b]])) for b in range(share.shape[-1])
                    if touching[..., b].any()]
    per_scheme = [100 * touching[i].sum() / ran[i].sum() for i in range(len(ds.scheme)) if ran[i].any()]
    surface = "tilt_status" in ds and bool(np.any(ds.tilt_status.values != flag(ds.tilt_status, "not_computed")))
    counted = surface or ("h_min_midplane" in ds and bool(np.any(ds.h_min.values[ran] < ds.h_min_midplane.values[ran])))
    counts = (int(ran.sum()), int(touching.sum()), per_scheme, per_position, 1 - ECCENTRICITY_LIMIT)
    if not counted:  # a study that read the mid-plane film: where and when its edges touched was not kept
        return EdgeContact(*counts, counted=False)
    rows = {}
    for b, bearing in enumerate(ds.bearing.values):
        on, there = touching[..., b], ran[..., b]
        if not on.any():
            continue
        lo, hi = np.percentile(share[..., b][there], [5, 95])
        rows[int(bearing)] = {"touching_pct": 100 * on.sum() / there.sum(),
                              "cycle_share": float(np.median(share[..., b][on])),
                              "cycle_lo": float(lo), "cycle_hi": float(hi),
                              "film": float(np.median(ds.h_min.values[..., b][on])),
                              "load": _median_of_recorded(ds.edge_contact_load.values[..., b][on]),
                              "angle": _median_of_recorded(ds.edge_contact_angle.values[..., b][on])}
    table = pd.DataFrame.from_dict(rows, orient="index")
    if not surface:
        return EdgeContact(*counts, per_position=table)
    return EdgeContact(*counts, surface=True, critical=Wear.of(ds).critical_film_m, per_position=table,
                       periodic=float(np.mean(ds.tilt_status.values[ran] == flag(ds.tilt_status, "periodic"))),
                       unresolved=_unresolved(ds, ran))


def _median_of_recorded(values):
    """The median of the values recorded (not NaN), NaN where none is (a tier that records no edge load)."""
    recorded = values[np.isfinite(values)]
    return float(np.median(recorded)) if recorded.size else np.nan


def _unresolved(ds, ran):
    """Median and 95 % of ``tilt_unresolved`` over the bearing-cycles that ran (NaN for a study before it)."""
    if "tilt_unresolved" not in ds:
        return (np.nan, np.nan)
    values = ds.tilt_unresolved.values[ran]
    values = values[np.isfinite(values)]
    return tuple(float(v) for v in np.percentile(values, [50, 95])) if values.size else (np.nan, np.nan)


@dataclass(frozen=True)
class FilmOutcomes:
    """How the films the chain computed ended (``film_status``), counted over bearing-cycles."""

    computed: int                # bearing-cycles the chain ran
    not_a_number: dict           # status -> count, the statuses whose film is NaN (only those that occurred)
    engines_not_a_number: int    # engines with such a bearing
    periodic: int
    edge_contact: int


def film_outcomes(ds):
    """The :class:`FilmOutcomes` of a study, or None without a film stage."""
    if "film_status" not in ds:
        return None
    status = ds.film_status
    ran = _computed(ds)

    def count(meaning):
        return int(np.count_nonzero(ran & (status.values == flag(status, meaning))))

    failed = {m: count(m) for m in NOT_A_NUMBER if count(m)}
    engines = int(np.count_nonzero(np.any(ran & ~ds.film_valid.values, axis=-1)))
    return FilmOutcomes(int(np.count_nonzero(ran)), failed, engines, count("periodic"), count("edge_contact"))


def film_detail(ds):
    """Per scheme and position, medians over engines: tilt, edge contact, edge film and peak film pressures.

    Columns: ``tilt_max`` [rad] (largest over the cycle), ``touching`` (share
    of the engines whose journal edge touches the bearing), ``edge_share``
    (share of the cycle it touches, over those engines; NaN where none does
    or the dataset predates it), ``edge_film`` [m] (over the engines whose
    edge does not touch; NaN where all do), ``p_max`` and ``p_max_mean`` [Pa]
    (peak film pressure over the cycle and its cycle mean). Films that are
    not a number are left out; empty without a film stage.
    """
    if "film_status" not in ds:
        return pd.DataFrame()
    rows = []
    edge_flag = flag(ds.film_status, "edge_contact")
    for i, scheme in enumerate(ds.scheme.values):
        done = converged_engines(ds, i)
        if not done.any():
            continue
        contact = ds.film_status.values[i, done] == edge_flag
        for b, bearing in enumerate(ds.bearing.values):
            number = ds.film_valid.values[i, done, b]
            if number.any():
                rows.append({"scheme": str(scheme), "bearing": int(bearing),
                             **_position_detail(ds, i, done, b, number, contact[number, b])})
    return pd.DataFrame(rows).set_index(["scheme", "bearing"]) if rows else pd.DataFrame()


def _position_detail(ds, i, done, b, number, touching):
    """One position's :func:`film_detail` columns (``number``: its films that are numbers, ``touching`` of them)."""
    def median(name, where=slice(None)):
        with warnings.catch_warnings():  # an all-NaN sample is NaN, said as such
            warnings.simplefilter("ignore", RuntimeWarning)
            return float(np.nanmedian(ds[name].values[i, done, b][where]))

    edge = ds.h_min_edge.values[i, done, b][number]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        edge_film = float(np.nanmedian(edge[~touching])) if (~touching).any() else np.nan
    shares = ds.edge_contact_share.values[i, done, b][number][touching] if "edge_contact_share" in ds else []
    return {"tilt_max": median("tilt_max"), "touching": float(touching.mean()),
            "edge_share": float(np.nanmedian(shares)) if len(shares) else np.nan, "edge_film": edge_film,
            "p_max": median("p_max"), "p_max_mean": median("p_max_mean")}


@dataclass(frozen=True)
class HeatBalance:
    """Film temperature [degC], friction power [W] and oil flow [L/min] per bearing: (5 %, median, 95 %)."""

    film_temperature: tuple
    friction_power: tuple
    oil_flow_l_min: tuple


def heat_balance(ds):
    """The :class:`HeatBalance` over the bearings whose film is a number, or None (no heat balance, no film)."""
    if not {"film_temperature", "friction_power", "oil_flow", "film_status"} <= set(ds.data_vars):
        return None
    valid = _computed(ds) & ds.film_valid.values
    if not valid.any():
        return None

    def spread(name, scale=1.0):
        return tuple(np.nanpercentile(ds[name].values[valid] * scale, [5, 50, 95]))

    return HeatBalance(spread("film_temperature"), spread("friction_power"), spread("oil_flow", 6e4))


@dataclass(frozen=True)
class Positions:
    """Why film and life differ by position: loads and films per position, the heaviest and thinnest."""

    load_kn: pd.Series           # cycle-maximum load per position [kN], mean over schemes of the engines' mean
    film_um: pd.Series           # median cycle-minimum film per position [um], mean over schemes
    heaviest: list               # positions within POSITION_SHARE of the largest load
    thinnest: list               # positions within POSITION_SHARE of the thinnest film


def positions(ds, bearings=None):
    """The :class:`Positions` of a study whose film ran (``bearings``: its :func:`bearing_summary`, if made)."""
    load = crank_summary(ds).groupby(level="bearing").mean_kn.mean()
    film = (bearing_summary(ds) if bearings is None else bearings).reset_index()
    film = film.assign(h=[q[0] for q in film.h_min_median_um]).groupby("bearing").h.mean()
    heavy = sorted(load.index[load >= load.max() - POSITION_SHARE * (load.max() - load.min())])
    thin = sorted(film.index[film <= film.min() + POSITION_SHARE * (film.max() - film.min())])
    return Positions(load, film, heavy, thin)


@dataclass(frozen=True)
class ClearanceTrends:
    """How film and life follow the operating clearance per position: Spearman's rank correlations over every
    scheme's bearings of the mechanical chain (the schemes give different clearances to the same response)."""

    film: pd.Series              # per position: rank correlation of the cycle-minimum film with the clearance
    life: pd.Series              # per position: rank correlation of method 1's life with the clearance
    pairs: int                   # bearings of the fewest-populated position

    @property
    def opposed(self):
        """The positions where the life lengthens with the clearance while the cycle-minimum film thins."""
        return [int(b) for b in self.film.index if self.film[b] < 0 < self.life[b]]


def clearance_trends(ds):
    """The :class:`ClearanceTrends` of a study that keeps every engine and ran its film (else None)."""
    if kept_summaries(ds) or "clearance_operating" not in ds or "life" not in ds:
        return None
    m = ds.sizes["mech_engine"]
    done = np.stack([ds.crank_status.values[i] == flag(ds.crank_status, "converged")
                     for i in range(ds.sizes["scheme"])])
    film, life, pairs = {}, {}, []
    for b, bearing in enumerate(ds.bearing.values):
        c = ds.clearance_operating.values[:, :m, b][done]
        h, hours = ds.h_min.values[:, :, b][done], ds.life.values[:, :, b][done]
        ok = np.isfinite(c) & np.isfinite(h) & np.isfinite(hours)
        if np.count_nonzero(ok) < 3:
            return None
        film[int(bearing)] = float(stats.spearmanr(c[ok], h[ok]).statistic)
        life[int(bearing)] = float(stats.spearmanr(c[ok], hours[ok]).statistic)
        pairs.append(int(np.count_nonzero(ok)))
    return ClearanceTrends(pd.Series(film), pd.Series(life), min(pairs))


@dataclass(frozen=True)
class LifeBias:
    """What the film tier's error on the cycle-mean film does to method 1's life at the study's median film."""

    error: float                 # the tier's largest error on the cycle-mean film, a share of the reference [-]
    film: float                  # the study's median cycle-mean film [m]
    life_h: float                # method 1's life at that film [h]
    thinner_life_h: float        # at the film thinner by the error, film / (1 + error) [h]
    cap_h: float                 # method 1's longest life, wear limit / wear speed [h]


def life_bias(ds):
    """The :class:`LifeBias` of a study, or None (no measured error of its tier, no cycle-mean film, no error).

    The tier's largest error on the cycle mean (always thick, reports/film_speed_vs_error.md) taken off the
    median cycle-mean film of the bearings the chain ran; lives by the study's method 1 and constants.
    """
    errors = FilmErrors.of(ds)
    if errors is None or "wear" not in ds.attrs or "h_min_mean" not in ds:
        return None
    films = ds.h_min_mean.values
    films = films[np.isfinite(films)]
    if not films.size or errors.h_min_mean <= 0:
        return None
    wear = Wear.of(ds)
    h = float(np.median(films))
    # the study stores lives at its bearings' own films only, not at these two: method 1 is evaluated here
    lives = levanov_method1(np.array([h, h / (1 + errors.h_min_mean)]), h_lim_cr=wear.critical_film_m,
                            wear_limit=wear.method1_limit_m, wear_rate=wear.wear_rate_m_per_s).life / 3600
    return LifeBias(errors.h_min_mean, h, float(lives[0]), float(lives[1]),
                    wear.method1_limit_m / wear.wear_rate_m_per_s / 3600)
