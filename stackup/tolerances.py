"""Drawing limits, manufacturing processes and gauges of one dimension.

A *process* is the distribution of the true size a machine makes; a *gauge*
turns a true size into the reading that grading sees; a :class:`Dimension`
puts drawing limits, process, gauge and the share of variance that parts of one
group (the bores of one block, the journals of one crankshaft) have in common.

Every process maps standard normal variates to sizes through its quantile
function, ``x = F^{-1}(Phi(z))``, so correlated parts come from correlated
normals (a Gaussian copula) whatever the marginal distribution, and the same
random numbers serve every scheme of a comparison (common random numbers).
All sizes are in metres.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from functools import cached_property

import numpy as np
from scipy import special, stats

from . import _validate as check

#: Points of the tabulated CDF used to invert processes without a closed-form
#: quantile (mixtures, tool wear). Over +-10 sigma this spacing keeps the
#: interpolated quantile within 1e-5 sigma of the exact one (tested).
_QUANTILE_GRID = 8193


@dataclass(frozen=True)
class Normal:
    """Normal process with mean ``mean`` [m] and standard deviation ``sigma`` [m]."""

    mean: float
    sigma: float

    @classmethod
    def from_capability(cls, lo, hi, *, cpk, cp=None, side="upper"):
        r"""Normal process from capability indices over drawing limits [lo, hi].

        :math:`\sigma = (hi - lo)/(6 C_p)` and the mean sits
        :math:`3\sigma (C_p - C_{pk})` off the mid-tolerance towards ``side``
        ("upper" or "lower"). Without ``cp`` the process is centred
        (:math:`C_p = C_{pk}`).
        """
        cpk = float(check.positive("cpk", cpk))
        cp = cpk if cp is None else float(check.positive("cp", cp))
        if cp < cpk:
            raise ValueError(f"cp: {cp!r} is below cpk {cpk!r}; cp >= cpk always")
        check.one_of("side", side, ("upper", "lower"))
        sigma = (hi - lo) / (6.0 * cp)
        offset = 3.0 * sigma * (cp - cpk)
        mid = 0.5 * (lo + hi)
        return cls(mid + offset if side == "upper" else mid - offset, sigma)

    @property
    def std(self):
        return self.sigma

    def from_normal(self, z):
        return self.mean + self.sigma * np.asarray(z)

    def cdf(self, x):
        return special.ndtr((np.asarray(x) - self.mean) / self.sigma)

    def ppf(self, u):
        return self.mean + self.sigma * special.ndtri(u)

    def shifted(self, delta):
        return replace(self, mean=self.mean + delta)


@dataclass(frozen=True)
class TruncatedNormal:
    """Normal(mean, sigma) [m] truncated to [lo, hi] [m] (a sorted or reworked population)."""

    mean: float
    sigma: float
    lo: float
    hi: float

    @cached_property
    def _dist(self):
        a = (self.lo - self.mean) / self.sigma
        b = (self.hi - self.mean) / self.sigma
        return stats.truncnorm(a, b, loc=self.mean, scale=self.sigma)

    @property
    def std(self):
        return float(self._dist.std())

    def from_normal(self, z):
        return self.ppf(special.ndtr(z))

    def cdf(self, x):
        return self._dist.cdf(x)

    def ppf(self, u):
        # scipy's quantile can round a hair outside the truncation bounds
        return np.clip(self._dist.ppf(u), self.lo, self.hi)

    def shifted(self, delta):
        return replace(self, mean=self.mean + delta, lo=self.lo + delta, hi=self.hi + delta)


@dataclass(frozen=True)
class Uniform:
    """Uniform process on [lo, hi] [m]."""

    lo: float
    hi: float

    @property
    def std(self):
        return (self.hi - self.lo) / np.sqrt(12.0)

    def from_normal(self, z):
        return self.lo + (self.hi - self.lo) * special.ndtr(z)

    def cdf(self, x):
        return np.clip((np.asarray(x) - self.lo) / (self.hi - self.lo), 0.0, 1.0)

    def ppf(self, u):
        return self.lo + (self.hi - self.lo) * np.asarray(u)

    def shifted(self, delta):
        return replace(self, lo=self.lo + delta, hi=self.hi + delta)


class _TabulatedQuantile:
    """Quantile by inverting a tabulated CDF (for processes without a closed form)."""

    def _support(self):
        raise NotImplementedError

    @cached_property
    def _table(self):
        lo, hi = self._support()
        x = np.linspace(lo, hi, _QUANTILE_GRID)
        u = self.cdf(x)
        # np.interp needs strictly increasing abscissae; flat CDF tails are cut.
        keep = np.concatenate(([True], np.diff(u) > 0))
        return u[keep], x[keep]

    def ppf(self, u):
        table_u, table_x = self._table
        return np.interp(u, table_u, table_x)

    def from_normal(self, z):
        return self.ppf(special.ndtr(z))


@dataclass(frozen=True)
class Mixture(_TabulatedQuantile):
    """Parts from several processes in given shares (two machines, two set-ups).

    ``components`` is a tuple of processes, ``weights`` their shares (summing to 1).
    """

    components: tuple
    weights: tuple

    def __post_init__(self):
        w = check.positive("mixture weights", self.weights)
        if len(w) != len(self.components) or len(w) < 1:
            raise ValueError(
                f"mixture weights: {len(w)} weights for {len(self.components)} components; give one weight each"
            )
        if abs(w.sum() - 1.0) > 1e-9:
            raise ValueError(f"mixture weights: they sum to {float(w.sum())!r}; they must sum to 1")

    @property
    def mean(self):
        return float(sum(w * _mean(c) for w, c in zip(self.weights, self.components)))

    @property
    def std(self):
        m = self.mean
        second = sum(w * (c.std**2 + (_mean(c) - m) ** 2) for w, c in zip(self.weights, self.components))
        return float(np.sqrt(second))

    def cdf(self, x):
        return sum(w * c.cdf(x) for w, c in zip(self.weights, self.components))

    def _support(self):
        lows = [_mean(c) - 10.0 * c.std for c in self.components]
        highs = [_mean(c) + 10.0 * c.std for c in self.components]
        return min(lows), max(highs)

    def shifted(self, delta):
        return Mixture(tuple(c.shifted(delta) for c in self.components), self.weights)


@dataclass(frozen=True)
class ToolWear(_TabulatedQuantile):
    r"""Mean drifting linearly from ``start`` to ``end`` [m] over a tool life, noise ``sigma`` [m].

    Parts are made uniformly over the tool life, so the size is
    :math:`x = a + t\,d + \sigma z` with :math:`t \sim U(0, 1)`, :math:`d = end - start`.
    Its CDF is closed-form with :math:`G(v) = v\,\Phi(v) + \varphi(v)`, the
    antiderivative of :math:`\Phi`:

    .. math:: F(x) = \frac{\sigma}{d}\left[G\!\left(\frac{x-a}{\sigma}\right)
                     - G\!\left(\frac{x-a-d}{\sigma}\right)\right]
    """

    start: float
    end: float
    sigma: float

    @property
    def mean(self):
        return 0.5 * (self.start + self.end)

    @property
    def std(self):
        return float(np.sqrt(self.sigma**2 + (self.end - self.start) ** 2 / 12.0))

    def cdf(self, x):
        d = self.end - self.start
        v = (np.asarray(x) - self.start) / self.sigma
        if abs(d) < 1e-9 * self.sigma:
            return special.ndtr(v)
        w = d / self.sigma

        def g(v):
            return v * special.ndtr(v) + np.exp(-0.5 * v * v) / np.sqrt(2.0 * np.pi)

        return np.clip((g(v) - g(v - w)) / w, 0.0, 1.0)

    def _support(self):
        lo, hi = sorted((self.start, self.end))
        return lo - 10.0 * self.sigma, hi + 10.0 * self.sigma

    def shifted(self, delta):
        return replace(self, start=self.start + delta, end=self.end + delta)


def _mean(process):
    if isinstance(process, Uniform):
        return 0.5 * (process.lo + process.hi)
    if isinstance(process, TruncatedNormal):
        return float(process._dist.mean())
    return process.mean


@dataclass(frozen=True)
class Gauge:
    """How a size is read: bias, repeatability, resolution and temperature.

    Parameters
    ----------
    bias : float
        Systematic error of the reading [m].
    repeatability : float
        Standard deviation of repeated readings of one part [m].
    resolution : float
        Step of the read-out [m]; 0 reads continuously. Readings are rounded
        to the nearest step.
    temperature : float
        Temperature at which parts are measured [degC]; the gauge is mastered at 20 degC.
    expansion_mismatch : float
        Thermal expansion of the part minus that of the gauge master [1/K];
        the reading grows by ``size * expansion_mismatch * (temperature - 20)``.
    """

    bias: float = 0.0
    repeatability: float = 0.0
    resolution: float = 0.0
    temperature: float = 20.0
    expansion_mismatch: float = 0.0

    def __post_init__(self):
        check.finite("gauge bias", self.bias)
        check.positive("gauge repeatability", self.repeatability, allow_zero=True)
        check.positive("gauge resolution", self.resolution, allow_zero=True)
        check.in_range("gauge temperature", self.temperature, -50.0, 200.0, unit=" degC")
        check.finite("gauge expansion_mismatch", self.expansion_mismatch)

    def read(self, true_size, z):
        """Reading of parts of true size ``true_size`` [m], given standard normals ``z``."""
        reading = true_size + self.bias + self.repeatability * z
        if self.expansion_mismatch:
            reading = reading + true_size * self.expansion_mismatch * (self.temperature - 20.0)
        return quantize(reading, self.resolution)


def quantize(value, step):
    """Round ``value`` [m] to the nearest multiple of ``step`` [m] (0 leaves it as it is)."""
    if step == 0:
        return value
    return np.round(np.asarray(value) / step) * step


@dataclass(frozen=True)
class Dimension:
    """Drawing limits, process and gauge of one dimension of a part.

    Parameters
    ----------
    name : str
        Domain name, e.g. ``"housing_bore"``.
    lo, hi : float
        Drawing limits [m]; parts read outside them are scrapped.
    process : process object
        Distribution of the true size [m].
    gauge : Gauge
        Measurement model.
    shared : float
        Share of the process variance common to one group of parts (the bores
        of one block, bored in one set-up; the journals of one crankshaft)
        [-], in [0, 1). It is the intra-group correlation of the true sizes.
    """

    name: str
    lo: float
    hi: float
    process: object
    gauge: Gauge = Gauge()
    shared: float = 0.0

    def __post_init__(self):
        check.limits(self.name, self.lo, self.hi)
        check.in_range(f"{self.name} shared", self.shared, 0.0, 1.0, hi_open=True)

    def true_sizes(self, z_group, z_part):
        """True sizes [m] of parts ``z_part`` (groups, parts) with group normals ``z_group`` (groups,)."""
        if self.shared:
            z = np.sqrt(self.shared) * z_group[:, None] + np.sqrt(1.0 - self.shared) * z_part
        else:
            z = z_part
        return self.process.from_normal(z)

    def outside(self, reading):
        """True where a reading [m] lies outside the drawing limits (part scrapped)."""
        return (reading < self.lo) | (reading > self.hi)

    def shifted(self, delta):
        """The same dimension with the process mean moved by ``delta`` [m]."""
        return replace(self, process=self.process.shifted(delta))


_DISTRIBUTIONS = ("normal", "truncated-normal", "uniform", "mixture", "tool-wear")


def process_from_spec(spec, *, lo, hi, scale, field):
    """Build a process from a TOML table (lengths in file units times ``scale`` -> m).

    Forms (lengths in the file's units)::

        {distribution = "normal", cpk = 1.33}                  # centred on [lo, hi]
        {distribution = "normal", cp = 1.67, cpk = 1.33, side = "upper"}
        {distribution = "normal", mean = 50.009, sigma = 0.002}
        {distribution = "truncated-normal", mean = ..., sigma = ..., lo = ..., hi = ...}
        {distribution = "uniform"}                             # lo, hi default to the limits
        {distribution = "mixture", components = [{weight = 0.6, distribution = ...}, ...]}
        {distribution = "tool-wear", start = ..., end = ..., sigma = ...}

    Any form takes ``mean_shift`` (added to the process mean).
    """
    spec = dict(spec)
    kind = check.one_of(f"{field}.distribution", spec.pop("distribution", "normal"), _DISTRIBUTIONS)
    shift = float(check.finite(f"{field}.mean_shift", spec.pop("mean_shift", 0.0))) * scale

    def length(key, default=None):
        if key not in spec:
            if default is None:
                raise ValueError(f"{field}: missing key '{key}' for distribution '{kind}'")
            return default
        return float(check.finite(f"{field}.{key}", spec.pop(key))) * scale

    def spread(key):
        value = length(key)
        if value <= 0:
            raise ValueError(f"{field}.{key}: {value / scale!r} is not valid; must be > 0")
        return value

    if kind == "normal":
        if "cpk" in spec:
            cpk = spec.pop("cpk")
            cp = spec.pop("cp", None)
            if cpk is None or float(cpk) <= 0:
                raise ValueError(f"{field}.cpk: {cpk!r} is not valid; must be > 0")
            process = Normal.from_capability(lo, hi, cpk=float(cpk), cp=cp, side=spec.pop("side", "upper"))
        else:
            process = Normal(length("mean", 0.5 * (lo + hi)), spread("sigma"))
    elif kind == "truncated-normal":
        process = TruncatedNormal(length("mean", 0.5 * (lo + hi)), spread("sigma"), length("lo", lo), length("hi", hi))
        if process.hi <= process.lo:
            raise ValueError(f"{field}: truncation hi {process.hi:.6g} m is not above lo {process.lo:.6g} m")
    elif kind == "uniform":
        process = Uniform(length("lo", lo), length("hi", hi))
        if process.hi <= process.lo:
            raise ValueError(f"{field}: uniform hi {process.hi:.6g} m is not above lo {process.lo:.6g} m")
    elif kind == "mixture":
        items = spec.pop("components", None)
        if not items:
            raise ValueError(f"{field}.components: a mixture needs at least one component")
        weights = tuple(float(c.get("weight", np.nan)) for c in items)
        comps = tuple(
            process_from_spec({k: v for k, v in c.items() if k != "weight"}, lo=lo, hi=hi, scale=scale,
                              field=f"{field}.components[{i}]")
            for i, c in enumerate(items)
        )
        process = Mixture(comps, weights)
    else:
        process = ToolWear(length("start"), length("end"), spread("sigma"))
    if spec:
        raise ValueError(f"{field}: unknown key(s) {sorted(spec)} for distribution '{kind}'")
    return process.shifted(shift) if shift else process


def gauge_from_spec(spec, *, scale, field):
    """Build a :class:`Gauge` from a TOML table (lengths in file units times ``scale``)."""
    spec = dict(spec or {})
    known = {"bias", "repeatability", "resolution", "temperature", "expansion_mismatch"}
    unknown = set(spec) - known
    if unknown:
        raise ValueError(f"{field}: unknown key(s) {sorted(unknown)}; valid: {sorted(known)}")
    for key in ("bias", "repeatability", "resolution"):
        if key in spec:
            spec[key] = float(check.finite(f"{field}.{key}", spec[key])) * scale
    try:
        return Gauge(**spec)
    except ValueError as err:
        raise ValueError(f"{field}: {err}") from None
