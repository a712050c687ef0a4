"""Sampled parts of one production lot: true sizes, readings, scrap.

A lot is ``lot_engines`` engines (blocks and crankshafts) and the shells made
for them. Each lot draws its random numbers from its own generator (see
:mod:`stackup._random`) in a fixed order, so a lot's parts do not depend on
how lots are grouped into chunks. Shells use the same standard normals for
every scheme and are mapped through each scheme's own shell process, so
schemes are compared on common random numbers.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np

from scipy import optimize, special
from scipy.stats import qmc

from .tolerances import Dimension, Gauge, process_from_spec


@dataclass(frozen=True)
class BlockParts:
    """Housing bores and journals of ``n`` engines with ``B`` main bearings each, in m."""

    housing_bore: np.ndarray  # (n, B) true bore
    housing_reading: np.ndarray  # (n, B) gauge reading
    journal_d: np.ndarray  # (n, B) true journal diameter
    journal_reading: np.ndarray  # (n, B)
    block_scrapped: np.ndarray  # (n,) a bore read outside its drawing limits
    crank_scrapped: np.ndarray  # (n,) a journal read outside its drawing limits
    bore_offset: np.ndarray  # (n, B, 2) bore centre off the straight line (coaxiality)
    journal_eccentricity: np.ndarray  # (n, B, 2) journal centre off the crankshaft axis at crank angle 0 (run-out)


@dataclass(frozen=True)
class ShellNormals:
    """Random numbers of the shells made in one lot: normals of wall, wall gauge and crush height, and the order.

    ``order`` (uniform keys, optional) is the order in which a lot's shells
    reach the bins: a lot made to order is produced grade after grade, but its
    shells are sorted into bins that mix them, so the shells a bin gives out
    first are not those aimed at one grade. None keeps production order.
    """

    size: np.ndarray
    gauge: np.ndarray
    crush: np.ndarray
    order: np.ndarray | None = None

    # A designer scores thousands of shell grades on the same normals: what follows from them alone is
    # computed once (the caches live in the instance, so they go with the normals).

    @cached_property
    def arrival(self):
        """Permutation of a lot's shells into the order they reach the bins (None: production order)."""
        return None if self.order is None else np.argsort(self.order, kind="stable")

    def gauge_error(self, gauge):
        """Repeatability error of each shell's reading with ``gauge`` [m] (:meth:`Gauge.noise`), cached per gauge."""
        cache = self.__dict__.setdefault("_gauge_error", {})
        if gauge not in cache:
            cache[gauge] = gauge.noise(self.gauge)
        return cache[gauge]


@dataclass(frozen=True)
class Shells:
    """Shells of one lot made for one scheme, in production order."""

    wall: np.ndarray  # true crown wall thickness [m]
    reading: np.ndarray  # measured wall [m]
    crush: np.ndarray  # crush height [m]
    grade: np.ndarray  # grade index in the scheme, -1 = scrapped (wall read outside every grade, or crush out of limits)


SAMPLERS = ("mc", "qmc")


def _engine_normals(engine, rng, n_engines, sampler):
    """Standard normals of each engine's parts, (engines, 2 + 8 B) in a fixed column layout.

    Columns: block, crankshaft, bores (B), bore gauge (B), journals (B),
    journal gauge (B), bore offsets (2B), journal eccentricities (2B).
    ``"qmc"``: each engine is a point of a scrambled Sobol sequence (scrambled
    by the lot's generator, so lots are independent randomised-QMC
    replicates and the estimate stays unbiased).
    """
    b = engine.main_bearings
    d = 2 + 8 * b
    if sampler == "mc":
        return None
    sobol = qmc.Sobol(d, scramble=True, seed=rng)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)  # balance needs 2^m points; lots need not be
        u = sobol.random(n_engines)
    return special.ndtri(np.clip(u, 1e-16, 1 - 1e-16))


def draw_lot(engine, rng, n_engines, sampler="mc"):
    """Draw the blocks, crankshafts and shell normals of one lot of ``n_engines`` engines.

    The order of draws is fixed: block normals, bore normals, bore gauge,
    crankshaft normals, journal normals, journal gauge, shell normals, shell
    gauge, shell crush, bore offsets, journal eccentricities; then, only for
    an engine that has them, bore form errors, journal form errors and the
    bolt-tension scatter of the bores.

    Readings see each part's form error as read (:class:`stackup.tolerances.FormError`);
    ``housing_bore`` is the bore at assembly: the bore read plus its change
    from bolting the cap again (``bolt_scatter``).

    Misalignment: each component of a bore offset is normal with standard
    deviation coaxiality / 8 (the centre stays inside the coaxiality zone of
    diameter t with probability 1 - exp(-8) = 0.9997), each component of a
    journal eccentricity likewise with run-out / 8 (run-out reads twice the
    eccentricity).
    """
    b = engine.main_bearings
    hb, jd = engine.housing_bore, engine.journal_d
    z = _engine_normals(engine, rng, n_engines, sampler)
    if z is None:
        z_block = rng.standard_normal(n_engines)
        z_bore = rng.standard_normal((n_engines, b))
        g_bore = rng.standard_normal((n_engines, b))
        z_crank = rng.standard_normal(n_engines)
        z_journal = rng.standard_normal((n_engines, b))
        g_journal = rng.standard_normal((n_engines, b))
    else:
        z_block, z_crank = z[:, 0], z[:, 1]
        z_bore, g_bore, z_journal, g_journal = (z[:, 2 + k * b:2 + (k + 1) * b] for k in range(4))
    n_shells = engine.shell_wall.shells_per_lot(n_engines * b)
    shells = ShellNormals(rng.standard_normal(n_shells), rng.standard_normal(n_shells), rng.standard_normal(n_shells))
    coaxiality = engine.crank.coaxiality if engine.crank else 0.0
    runout = engine.crank.journal_runout if engine.crank else 0.0
    if z is None:
        z_offset = rng.standard_normal((n_engines, b, 2))
        z_ecc = rng.standard_normal((n_engines, b, 2))
    else:
        z_offset = z[:, 2 + 4 * b:2 + 6 * b].reshape(n_engines, b, 2)
        z_ecc = z[:, 2 + 6 * b:].reshape(n_engines, b, 2)
    bore_offset = coaxiality / 8 * z_offset
    eccentricity = runout / 8 * z_ecc
    # Drawn after the layout above, and only for engines that have them, so every other engine's
    # streams stay as they were (pseudo-random also under "qmc"): form errors, bolt-tension scatter.
    z_form_bore = rng.standard_normal((n_engines, b, 3)) if hb.form is not None else None
    z_form_journal = rng.standard_normal((n_engines, b, 3)) if jd.form is not None else None
    z_bolt = rng.standard_normal((n_engines, b)) if hb.bolt_scatter else None
    shells = replace(shells, order=rng.random(n_shells))

    bore = hb.true_sizes(z_block, z_bore)
    bore_reading = hb.read(bore, g_bore, z_form_bore)
    if z_bolt is not None:  # bolted again at assembly: the bore the shells see is not the one read
        bore = bore + hb.bolt_scatter * z_bolt
    journal = jd.true_sizes(z_crank, z_journal)
    journal_reading = jd.read(journal, g_journal, z_form_journal)
    parts = BlockParts(
        housing_bore=bore,
        housing_reading=bore_reading,
        journal_d=journal,
        journal_reading=journal_reading,
        block_scrapped=hb.outside(bore_reading).any(axis=1),
        crank_scrapped=jd.outside(journal_reading).any(axis=1),
        bore_offset=bore_offset,
        journal_eccentricity=eccentricity,
    )
    return parts, shells


@dataclass(frozen=True)
class ShellSupply:
    """How the shells of a lot are made for a scheme and sorted into its grades.

    Two modes:

    ``"to-order"``
        Each grade is made in a planned quantity (the expected share of the
        grade in the scheme's demand, times the lot's shells) by the wall
        process aimed at the grade centre (plus ``target_offset``) with
        standard deviation ``sigma``. Shells are read and sorted by their
        reading, so a shell aimed at one grade may land in its neighbour's bin.
    ``"sorted"``
        One process, stated over the scheme's whole shell range (``process``,
        e.g. ``cpk = 1.33``), sorted into grades by the reading: grade
        quantities follow the process, not the demand.

    In both, a shell read outside every grade, or with its crush height
    outside the crush limits, is scrapped, and a lot makes
    ``ceil(2 * bearings * (1 + surplus))`` shells.

    Parameters
    ----------
    mode : {"to-order", "sorted"}
    process : dict
        Process table (TOML form, file units) for ``"sorted"``.
    sigma : float or None
        Wall process standard deviation [m] for ``"to-order"``.
    target_offset : float
        Offset of the process aim from the grade centre [m] (``"to-order"``).
    gauge : Gauge
        Wall-thickness gauge.
    lot_engines : int
        Engines per production lot of shells.
    surplus : float
        Share of shells made on top of two per bearing [-].
    scale : float
        File length unit [m].
    crush : Dimension
        Crush height per half shell: limits and process [m].
    """

    mode: str
    process: dict
    sigma: float | None
    target_offset: float
    gauge: Gauge
    lot_engines: int
    surplus: float
    scale: float
    crush: Dimension

    def dimension(self, scheme):
        """The ``"sorted"`` shell wall :class:`Dimension` for ``scheme``: limits = its shell range."""
        lo, hi = scheme.shell.limits
        process = process_from_spec(self.process, lo=lo, hi=hi, scale=self.scale, field="shell_wall.process")
        return Dimension("shell_wall", lo, hi, process, self.gauge)

    def shells_per_lot(self, bearings):
        """Shells made for a lot of ``bearings`` bearings."""
        return math.ceil(2 * bearings * (1.0 + self.surplus))

    def _aim(self, scheme):
        return 0.5 * (scheme.shell.lo + scheme.shell.hi) + self.target_offset

    def spill(self, scheme):
        r"""Probability that a shell aimed at grade g is read into grade g' (g', g).

        The reading of a shell aimed at centre :math:`m_g` is taken as normal
        with the mean and spread of wall plus gauge error,
        :math:`m_g + \mu_{gauge}` and :math:`s = \sqrt{\sigma^2 + \sigma_{gauge}^2}`
        (resolution ignored; the larger of two readings has
        :math:`\mu_{gauge} = 0.56\,\sigma_r`, :math:`\sigma_{gauge} = 0.83\,\sigma_r`),
        so :math:`P_{g'g} = \Phi((b_{g'} - m_g)/s) - \Phi((a_{g'} - m_g)/s)`
        over the reading range :math:`[a_{g'}, b_{g'})` of grade g'.
        """
        bias, spread = self.gauge.noise_moments()
        s = np.hypot(self.sigma, spread)
        lo, hi = scheme.shell.bins()
        m = self._aim(scheme) + bias
        return special.ndtr((hi[:, None] - m[None, :]) / s) - special.ndtr((lo[:, None] - m[None, :]) / s)

    def aim_share(self, scheme, demand_share):
        """Share of the lot aimed at each grade so the bins hold the demanded mix (``"to-order"``).

        Non-negative least squares on the spill matrix, ``min ||P q - d||`` with
        ``q >= 0`` (the planner's compensation for shells landing in a
        neighbour's bin), normalised to sum 1.
        """
        d = np.asarray(demand_share, dtype=float)
        q, _ = optimize.nnls(self.spill(scheme), d / d.sum())
        return q / q.sum()

    def make(self, scheme, normals, aim_share=None):
        """The shells of one lot for ``scheme`` from the lot's shell normals.

        ``aim_share`` (grades,) is the share of the lot aimed at each grade
        (from :meth:`aim_share`); ``"to-order"`` needs it.
        """
        if self.mode == "sorted":
            wall = self.dimension(scheme).process.from_normal(normals.size)
        else:
            centre = self._aim(scheme)
            quantity = apportion(aim_share, normals.size.size)
            wall = np.repeat(centre, quantity) + self.sigma * normals.size
            if normals.arrival is not None:  # made grade after grade, mixed in the bins
                wall = wall[normals.arrival]
        reading = self.gauge.reading(wall, normals.gauge_error(self.gauge))
        crush = self.crush.process.from_normal(normals.crush)
        grade = np.where(self.crush.outside(crush), -1, scheme.shell.classify(reading))
        return Shells(wall, reading, crush, grade)


def apportion(share, total):
    """Whole quantities summing to ``total`` in proportion to ``share`` (largest remainder)."""
    share = np.asarray(share, dtype=float)
    exact = share / share.sum() * total
    quantity = np.floor(exact).astype(np.int64)
    short = total - quantity.sum()
    quantity[np.argsort(-(exact - quantity), kind="stable")[:short]] += 1
    return quantity
