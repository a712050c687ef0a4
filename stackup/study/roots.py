r"""The study's chain as a function of independent root inputs, for sensitivity and tail estimators.

A study draws whole lots: which shell a bearing gets depends on the other
engines of its lot. Variance-based sensitivity (Sobol) and importance
sampling need the opposite: each output a deterministic function of
independent inputs of known distribution. Here one engine is built from its
own root inputs, uniform on [0, 1) (standard normals through
:math:`\Phi^{-1}` where a part's process is normal):

``housing bore``, ``journal``
    The block's (crankshaft's) common normal and each bore's (journal's) own
    normal, mixed by the engine's ``shared`` share as the study does.
``bore gauge error``, ``journal gauge error``
    The gauge's repeatability normal of each reading. A part read outside its
    drawing limits is graded at the limit: the analysis is of assembled
    bearings (scrap is a separate share in the study).
``bore form error``, ``journal form error``, ``bolt tension``
    Where the engine file declares them: each part's ovality, its angle and
    taper (three normals, :class:`~stackup.tolerances.FormError`), and the
    change of a bore between its reading and assembly (one normal each).
``shell wall``, ``shell gauge error``
    The shell a bearing receives is a shell *read* into the grade its pair
    asks for, taken from the grade's bin (the stock). Its reading is drawn
    from the bin's distribution of readings, and its true wall from the
    distribution of true walls given that reading:
    :math:`t = x - e` with :math:`e \mid x` normal with mean
    :math:`k (x - m_a)` and variance :math:`\sigma^2 r^2 / s^2`, where
    :math:`m_a` is the aim of the production the shell came from,
    :math:`s^2 = \sigma^2 + r^2`, :math:`k = r^2/s^2` (a normal wall process
    :math:`\sigma`, gauge repeatability :math:`r`). Shells made to order are
    a mixture over the grades' aims with the lot's planned shares (the
    pilot's :func:`~stackup.study.pilot.shell_plan`), so spill from a
    neighbour's aim is included. ``shell wall`` is the reading's position in
    the bin, ``shell gauge error`` the true wall's position given the reading:
    together they are the shell's process and gauge (Rosenblatt's
    transformation, reading first).
``crush height``
    Each shell's crush height, its process truncated to the drawing limits
    (shells outside them are scrapped before sorting).
``bore process mean``, ``journal process mean``
    A shift of the process mean, uniform over plus or minus ``mean_shift``
    standard deviations; the shell plan does not follow it, as a plant's
    planning would not.
``misalignment``
    Each bore's coaxiality offset and each journal's run-out eccentricity
    (two normals each), as the study samples them.

Pairs are the scheme's preferred pairs: the bins are not allowed to run
short here (stock-outs are the study's business), and the readings are
rounded to the scheme's read-out as in the study.

References
----------
.. [1] Rosenblatt, M., "Remarks on a multivariate transformation", Ann. Math.
   Statist. 23 (1952) 470-472.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import special

from ..tolerances import process_mean
from .clearance import operating_clearance, preferred_pairs

#: Root-input groups, in the order of the columns (see :meth:`RootModel.columns`); an engine has
#: those of them its file declares (:attr:`RootModel.groups`).
GROUPS = ("housing bore", "journal", "bore gauge error", "journal gauge error", "bore form error",
          "journal form error", "bolt tension", "shell wall", "shell gauge error", "crush height",
          "bore process mean", "journal process mean", "misalignment")
#: Largest |z| a uniform input maps to: keeps Phi^-1 finite at u = 0 (Sobol points start there).
Z_MAX = 8.0


def _normal(u):
    return special.ndtri(np.clip(u, special.ndtr(-Z_MAX), special.ndtr(Z_MAX)))


@dataclass(frozen=True)
class ShellBins:
    """The distribution of the shells in each grade's bin: aims, shares and the wall and gauge spreads.

    Attributes
    ----------
    lo, hi : numpy.ndarray (grades,)
        Readings sorted into each grade [m].
    aims : numpy.ndarray (aims,)
        Centres of the productions that feed the bins [m].
    shares : numpy.ndarray (aims,)
        Share of the shells made at each aim [-].
    sigma, gauge : float
        Wall process and gauge (combined reading) standard deviations [m].
    bias : float
        Mean of the combined reading's error [m] (the larger of two readings reads high).
    """

    lo: np.ndarray
    hi: np.ndarray
    aims: np.ndarray
    shares: np.ndarray
    sigma: float
    gauge: float
    bias: float = 0.0

    @classmethod
    def of(cls, engine, scheme, aim_share):
        """The bins of ``scheme``'s shells made by ``engine``'s supply (``aim_share``: the lot's plan, or None)."""
        supply = engine.shell_wall
        lo, hi = scheme.shell.bins()
        bias, spread = supply.gauge.noise_moments()
        if supply.mode == "to-order":
            return cls(lo, hi, np.asarray(supply._aim(scheme), float), np.asarray(aim_share, float),
                       float(supply.sigma), float(spread), float(bias))
        process = supply.dimension(scheme).process
        return cls(lo, hi, np.array([process_mean(process)]), np.array([1.0]), float(process.std), float(spread),
                   float(bias))

    @property
    def spread(self):
        """Standard deviation of a reading about its aim [m]."""
        return float(np.hypot(self.sigma, self.gauge))

    def reading(self, grade, u):
        """Reading [m] at position ``u`` in [0, 1) of the bin of ``grade`` (arrays of equal shape)."""
        s = self.spread
        lo, hi = self.lo[grade], self.hi[grade]
        centres = self.aims + self.bias  # where the readings of each production centre
        weight = self.shares[None, :] * (special.ndtr((hi[:, None] - centres) / s)
                                         - special.ndtr((lo[:, None] - centres) / s))
        target = u * weight.sum(axis=1)
        low, high = lo.copy(), hi.copy()
        for _ in range(48):  # bisection on the mixture's CDF within the bin: to 1e-14 of the bin width
            mid = 0.5 * (low + high)
            below = (self.shares[None, :] * (special.ndtr((mid[:, None] - centres) / s)
                                             - special.ndtr((lo[:, None] - centres) / s))).sum(axis=1)
            under = below < target
            low = np.where(under, mid, low)
            high = np.where(under, high, mid)
        return 0.5 * (low + high)

    def true_wall(self, reading, u):
        """True wall [m] of a shell with ``reading``, at position ``u`` in [0, 1) of its distribution given the reading."""
        s = self.spread
        if self.gauge == 0.0:
            return reading
        k = self.gauge**2 / s**2
        sd = self.sigma * self.gauge / s
        centres = self.aims + self.bias
        # posterior share of each aim given the reading, then the gauge error's mixture quantile by bisection
        log_w = np.log(np.maximum(self.shares, 1e-300))[None, :] - 0.5 * ((reading[:, None] - centres) / s) ** 2
        w = np.exp(log_w - log_w.max(axis=1, keepdims=True))
        w /= w.sum(axis=1, keepdims=True)
        means = self.bias + k * (reading[:, None] - centres)
        low = means.min(axis=1) - Z_MAX * sd
        high = means.max(axis=1) + Z_MAX * sd
        target = np.clip(u, special.ndtr(-Z_MAX), special.ndtr(Z_MAX))
        for _ in range(48):
            mid = 0.5 * (low + high)
            under = (w * special.ndtr((mid[:, None] - means) / sd)).sum(axis=1) < target
            low = np.where(under, mid, low)
            high = np.where(under, high, mid)
        return reading - 0.5 * (low + high)


class RootModel:
    """One engine of a study from its root inputs (see the module docstring).

    Parameters
    ----------
    engine : Engine
    scheme : Scheme
    aim_share : numpy.ndarray or None
        The lot's planned share per shell grade (:func:`~stackup.study.pilot.shell_plan`).
    mean_shift : float
        Half-range of the process mean inputs [process standard deviations].
    bearings : int, optional
        Main bearings per engine built (default the engine's; 1 for a bearing on its own).
    """

    def __init__(self, engine, scheme, aim_share, *, mean_shift=1.0, bearings=None):
        self.engine, self.scheme, self.mean_shift = engine, scheme, mean_shift
        self.bins = ShellBins.of(engine, scheme, aim_share)
        self.b = engine.main_bearings if bearings is None else bearings
        b = self.b
        hb, jd = engine.housing_bore, engine.journal_d
        self._sizes = {"housing bore": 1 + b, "journal": 1 + b, "bore gauge error": b, "journal gauge error": b,
                       "bore form error": 3 * b if hb.form is not None else 0,
                       "journal form error": 3 * b if jd.form is not None else 0,
                       "bolt tension": b if hb.bolt_scatter else 0, "shell wall": 2 * b, "shell gauge error": 2 * b,
                       "crush height": 2 * b, "bore process mean": 1, "journal process mean": 1, "misalignment": 4 * b}

    @property
    def groups(self):
        """The root-input groups this engine has (:data:`GROUPS` its file declares)."""
        return tuple(g for g in GROUPS if self._sizes[g])

    def columns(self, groups=None):
        """Names of the root inputs in column order and the group of each, for the given groups (default all)."""
        names, owners = [], []
        for group in self.groups if groups is None else groups:
            names += [f"{group} {k}" for k in range(self._sizes[group])]
            owners += [group] * self._sizes[group]
        return names, owners

    def engines(self, u, groups=None):
        """Parts and operating clearance of engines with root inputs ``u`` (engines, columns) in [0, 1).

        Groups of the engine left out of ``groups`` sit at their median
        (0.5). Returns a dict of (engines, bearings) arrays under their
        dataset names: ``housing_bore``, ``journal_d``, the shells'
        ``shell_upper_wall``, ``shell_lower_wall``, ``shell_upper_crush``,
        ``shell_lower_crush`` and ``clearance_operating`` (NaN where not
        graded; :func:`stackup.study.clearance.operating_clearance`), and
        (engines, bearings, 2) ``bore_offset`` and ``journal_eccentricity``.
        """
        u = np.asarray(u, dtype=float)
        n, b = u.shape[0], self.b
        all_names, all_owners = self.columns()
        names, _ = self.columns(groups)
        full = np.full((n, len(all_names)), 0.5)
        full[:, [all_names.index(x) for x in names]] = u
        owners = np.array(all_owners)
        take = {g: full[:, owners == g] for g in self.groups}
        engine, scheme = self.engine, self.scheme
        hb, jd = engine.housing_bore, engine.journal_d
        shift_h = (2 * take["bore process mean"][:, 0] - 1) * self.mean_shift * hb.process.std
        shift_j = (2 * take["journal process mean"][:, 0] - 1) * self.mean_shift * jd.process.std
        zb, zj = _normal(take["housing bore"]), _normal(take["journal"])
        bore = hb.true_sizes(zb[:, 0], zb[:, 1:]) + shift_h[:, None]
        journal = jd.true_sizes(zj[:, 0], zj[:, 1:]) + shift_j[:, None]
        form = {part: _normal(take[f"{part} form error"]).reshape(n, b, 3) if f"{part} form error" in take else None
                for part in ("bore", "journal")}
        bore_read = np.clip(hb.read(bore, _normal(take["bore gauge error"]), form["bore"]), hb.lo, hb.hi)
        journal_read = np.clip(jd.read(journal, _normal(take["journal gauge error"]), form["journal"]), jd.lo, jd.hi)
        if "bolt tension" in take:  # bolted again at assembly: the bore the shells see is not the one read
            bore = bore + hb.bolt_scatter * _normal(take["bolt tension"])
        upper, lower = preferred_pairs(scheme, bore_read, journal_read)
        graded = upper >= 0
        walls = []
        for k, grade in enumerate((upper, lower)):
            g = np.where(graded, grade, 0).ravel()
            reading = self.bins.reading(g, take["shell wall"][:, k * b:(k + 1) * b].ravel())
            wall = self.bins.true_wall(reading, take["shell gauge error"][:, k * b:(k + 1) * b].ravel())
            walls.append(wall.reshape(n, b))
        crush_dim = engine.shell_wall.crush
        lo_c, hi_c = crush_dim.process.cdf(crush_dim.lo), crush_dim.process.cdf(crush_dim.hi)
        crush = crush_dim.process.ppf(lo_c + (hi_c - lo_c) * np.clip(take["crush height"], 0.0, 1.0 - 1e-15))
        shells = {"shell_upper_wall": walls[0], "shell_lower_wall": walls[1], "shell_upper_crush": crush[:, :b],
                  "shell_lower_crush": crush[:, b:]}
        fit = operating_clearance(engine, housing_bore=bore, journal_d=journal, upper_wall=walls[0],
                                  lower_wall=walls[1], upper_crush=shells["shell_upper_crush"],
                                  lower_crush=shells["shell_lower_crush"])
        z = _normal(take["misalignment"]).reshape(n, b, 4)
        crank = engine.crank
        coaxiality, runout = (crank.coaxiality, crank.journal_runout) if crank is not None else (0.0, 0.0)
        return {"housing_bore": bore, "journal_d": journal, **shells,
                "clearance_operating": np.where(graded, fit.clearance, np.nan),
                "bore_offset": coaxiality / 8 * z[..., :2], "journal_eccentricity": runout / 8 * z[..., 2:]}
