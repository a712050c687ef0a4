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
from functools import cache, cached_property

import numpy as np
from scipy import special, stats

from . import _validate as check
from ._files import UNITS
from ._validate import OneOf, Positive, validated

#: Points of the tabulated CDF used to invert processes without a closed-form
#: quantile (mixtures, tool wear), over +-10 sigma: fine enough for the
#: quantile to invert the CDF within the tolerance tests/test_tolerances.py asserts.
_QUANTILE_GRID = 8193


#: Sides a process mean may sit off the middle of its tolerance.
SIDES = ("upper", "lower")


def _cp_not_below_cpk(args):
    if args["cp"] is not None and float(args["cp"]) < float(args["cpk"]):
        raise ValueError(f"cp: {float(args['cp'])!r} is below cpk {float(args['cpk'])!r}; cp >= cpk always")


@dataclass(frozen=True)
class Normal:
    """Normal process with mean ``mean`` [m] and standard deviation ``sigma`` [m]."""

    mean: float
    sigma: float

    @classmethod
    @validated(relations=(_cp_not_below_cpk,), cpk=Positive(), cp=Positive(), side=OneOf(SIDES))
    def from_capability(cls, lo, hi, *, cpk, cp=None, side="upper"):
        r"""Normal process from capability indices over drawing limits [lo, hi].

        :math:`\sigma = (hi - lo)/(6 C_p)` and the mean sits
        :math:`3\sigma (C_p - C_{pk})` off the mid-tolerance towards ``side``
        ("upper" or "lower"). Without ``cp`` the process is centred
        (:math:`C_p = C_{pk}`).
        """
        cpk = float(cpk)
        cp = cpk if cp is None else float(cp)
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
        return float(sum(w * process_mean(c) for w, c in zip(self.weights, self.components)))

    @property
    def std(self):
        m = self.mean
        second = sum(w * (c.std**2 + (process_mean(c) - m) ** 2) for w, c in zip(self.weights, self.components))
        return float(np.sqrt(second))

    def cdf(self, x):
        return sum(w * c.cdf(x) for w, c in zip(self.weights, self.components))

    def _support(self):
        lows = [process_mean(c) - 10.0 * c.std for c in self.components]
        highs = [process_mean(c) + 10.0 * c.std for c in self.components]
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


#: Largest skewness a skew-normal distribution can have, :math:`\sqrt{2}(4-\pi)/(\pi-2)^{3/2}` (its
#: half-normal limit).
MAX_SKEWNESS = float(np.sqrt(2.0) * (4.0 - np.pi) / (np.pi - 2.0) ** 1.5)
#: Declared checks of a skew-normal's fields (:func:`stackup._validate.fields`).
_SKEW_NORMAL_CHECKS = {"mean": check.Finite(), "sigma": check.Positive(),
                       "skewness": check.InRange(-MAX_SKEWNESS, MAX_SKEWNESS, lo_open=True, hi_open=True)}


@dataclass(frozen=True)
class SkewNormal(_TabulatedQuantile):
    r"""Skew-normal process (Azzalini) of mean ``mean`` [m], standard deviation ``sigma`` [m] and skewness [-].

    The centred parameters (mean, standard deviation, Pearson's skewness
    :math:`\gamma_1`, :math:`|\gamma_1| <` :data:`MAX_SKEWNESS`) are what a
    fitted process reports; the direct ones follow from them with
    :math:`b = \sqrt{2/\pi}`, :math:`r = (2\gamma_1/(4-\pi))^{1/3}`,
    :math:`\mu_z = r/\sqrt{1+r^2}`, :math:`\delta = \mu_z/b`:

    .. math:: \alpha = \frac{\delta}{\sqrt{1-\delta^2}}, \quad
              \omega = \frac{\sigma}{\sqrt{1-\mu_z^2}}, \quad \xi = \mu - \omega\,\mu_z

    (shape, scale, location of ``scipy.stats.skewnorm``). A machining process
    that stops at one side of its size (grinding to size) is skewed.

    References
    ----------
    .. [1] Azzalini, A., *The Skew-Normal and Related Families*, Cambridge
       University Press, 2014, sec. 2.1 and 3.1.4 (centred parameters).
    """

    mean: float
    sigma: float
    skewness: float

    def __post_init__(self):
        check.fields(self, _SKEW_NORMAL_CHECKS, prefix="skew-normal ")

    @cached_property
    def direct(self):
        """Direct parameters (shape alpha [-], location xi [m], scale omega [m]) of ``scipy.stats.skewnorm``."""
        r = np.cbrt(2.0 * self.skewness / (4.0 - np.pi))
        mu_z = r / np.sqrt(1.0 + r * r)
        delta = mu_z / np.sqrt(2.0 / np.pi)
        omega = self.sigma / np.sqrt(1.0 - mu_z * mu_z)
        return float(delta / np.sqrt(1.0 - delta * delta)), float(self.mean - omega * mu_z), float(omega)

    @property
    def std(self):
        return self.sigma

    def cdf(self, x):
        # Phi(z) - 2 T(z, alpha) (Owen's T): scipy's skewnorm.cdf integrates numerically for some arguments
        alpha, xi, omega = self.direct
        z = (np.asarray(x) - xi) / omega
        return np.clip(special.ndtr(z) - 2.0 * special.owens_t(z, alpha), 0.0, 1.0)

    def _support(self):
        return self.mean - 10.0 * self.sigma, self.mean + 10.0 * self.sigma

    def shifted(self, delta):
        return replace(self, mean=self.mean + delta)


#: Probabilities of the ISO 22514-2 quantile capability index: X_0.135 %, X_50 %, X_99.865 %.
CPK_QUANTILES = special.ndtr(np.array([-3.0, 0.0, 3.0]))


def quantile_cpk(process, lo, hi):
    r"""Capability index of ``process`` over the limits [``lo``, ``hi``] [m], ISO 22514-2's quantile form.

    .. math:: C_{pk} = \min\left(\frac{U - X_{50}}{X_{99.865} - X_{50}}, \frac{X_{50} - L}{X_{50} - X_{0.135}}\right)

    with the process's quantiles; for a normal process this is the classic
    :math:`\min(U - \mu, \mu - L)/3\sigma`, and for a skewed or two-machine
    process it reads the tail that the limits face rather than the standard
    deviation. Reference: ISO 22514-2:2017, Statistical methods in process
    management - Capability and performance - Part 2.
    """
    low, mid, high = process.ppf(CPK_QUANTILES)
    return float(min((hi - mid) / (high - mid), (mid - lo) / (mid - low)))


def process_mean(process):
    """Mean [m] of a process object (normal, truncated normal, uniform, mixture, tool wear)."""
    if isinstance(process, Uniform):
        return 0.5 * (process.lo + process.hi)
    if isinstance(process, TruncatedNormal):
        return float(process._dist.mean())
    return process.mean


#: How several readings of one part make its reading (:class:`Gauge`).
COMBINE = ("mean", "max")
#: Declared checks of a gauge's fields (:func:`stackup._validate.fields`).
_GAUGE_CHECKS = {"bias": check.Finite(), "repeatability": check.Positive(zero=True),
                 "resolution": check.Positive(zero=True), "temperature": check.InRange(-50.0, 200.0, unit=" degC"),
                 "expansion_mismatch": check.Finite(), "readings": check.Integer(minimum=1),
                 "combine": check.OneOf(COMBINE)}
#: Declared checks of a form error's fields.
_FORM_CHECKS = {"ovality": check.Positive(zero=True), "taper": check.Positive(zero=True),
                "planes": check.InRange(0.0, 1.0), "directions": check.Integer(minimum=1)}
#: Declared checks of a dimension's fields (the limits are a pair: :func:`stackup._validate.limits`).
_DIMENSION_CHECKS = {"shared": check.InRange(0.0, 1.0, hi_open=True), "bolt_scatter": check.Positive(zero=True)}


@dataclass(frozen=True)
class Gauge:
    r"""How a size is read: bias, repeatability, resolution and temperature.

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
    readings : int
        Readings taken of each part, each with its own repeatability error.
    combine : {"mean", "max"}
        How the readings make the part's reading: their mean (noise
        :math:`\sigma/\sqrt{k}`), or the largest (ISO 13778's measurement note
        for the shell wall: the larger of two readings).
    """

    bias: float = 0.0
    repeatability: float = 0.0
    resolution: float = 0.0
    temperature: float = 20.0
    expansion_mismatch: float = 0.0
    readings: int = 1
    combine: str = "mean"

    def __post_init__(self):
        check.fields(self, _GAUGE_CHECKS, prefix="gauge ")

    def noise(self, z):
        r"""Repeatability error of the combined reading [m] from one standard normal per part.

        The mean of :math:`k` readings is normal with :math:`\sigma/\sqrt{k}`.
        The largest of :math:`k` independent normal readings has the CDF
        :math:`\Phi(x)^k`, so it is drawn exactly from one normal :math:`z` as
        :math:`\Phi^{-1}(\Phi(z)^{1/k})` (inverse transform; one normal per
        part keeps the random streams of every reading rule the same).
        """
        z = np.asarray(z, dtype=float)
        if self.readings == 1:
            return self.repeatability * z
        if self.combine == "mean":
            return self.repeatability / np.sqrt(self.readings) * z
        return self.repeatability * special.ndtri(np.exp(special.log_ndtr(z) / self.readings))

    @cache  # a quadrature; a gauge is frozen (hashable), and designers ask thousands of times
    def noise_moments(self):
        """Mean and standard deviation of the combined reading's repeatability error [m]."""
        if self.readings == 1 or self.combine == "mean":
            return 0.0, self.repeatability / np.sqrt(self.readings)
        # moments of the largest of k standard normals, by quadrature of its density k phi Phi^(k-1)
        x = np.linspace(-10.0, 10.0, 20001)
        density = self.readings * stats.norm.pdf(x) * special.ndtr(x) ** (self.readings - 1)
        mean = np.trapezoid(x * density, x)
        std = np.sqrt(np.trapezoid((x - mean) ** 2 * density, x))
        return self.repeatability * mean, self.repeatability * std

    def read(self, true_size, z):
        """Reading of parts of true size ``true_size`` [m], given standard normals ``z``."""
        return self.reading(true_size, self.noise(z))

    def reading(self, true_size, error):
        """Reading of parts of true size ``true_size`` [m] whose repeatability error is ``error`` [m]."""
        reading = true_size + self.bias + error
        if self.expansion_mismatch:
            reading = reading + true_size * self.expansion_mismatch * (self.temperature - 20.0)
        return quantize(reading, self.resolution)


@dataclass(frozen=True)
class FormError:
    r"""Ovality and taper of round parts (journals), and where they are read.

    Each part has a two-lobe ovality :math:`o` (largest minus smallest
    diameter around the circumference) uniform in [0, ``ovality``] at a
    uniform angle, and a linear taper :math:`\tau` (diameter difference end to
    end) uniform in [-``taper``, ``taper``]:

    .. math:: d(x, \theta) = \bar d + \frac{o}{2}\cos 2(\theta - \theta_0) + \tau\,(x - 1/2)

    with :math:`x` the axial position as a share of the width and
    :math:`\bar d` the mean diameter (the size the clearance sees). The
    reading is the mean over ``planes`` and ``directions`` (equally spaced
    over 180 deg), so its form error is

    .. math:: e = \frac{o}{2}\,\overline{\cos 2(\theta_k - \theta_0)} + \tau\,(\bar x - 1/2):

    one 2-point reading sees up to :math:`o/2` of ovality; two directions
    90 deg apart cancel it; planes placed symmetrically cancel the taper
    (ISO 13778's note: journals may need several readings, axial and
    circumferential, to get their mean diameter).

    Parameters
    ----------
    ovality, taper : float
        Form tolerances [m] (the largest ovality and taper a part has).
    planes : tuple of float
        Axial reading positions, shares of the width in [0, 1].
    directions : int
        Reading directions per plane.
    """

    ovality: float
    taper: float
    planes: tuple = (0.5,)
    directions: int = 1

    def __post_init__(self):
        check.fields(self, _FORM_CHECKS, prefix="form ")
        if np.ndim(self.planes) != 1 or np.size(self.planes) == 0:
            raise ValueError(f"form planes: {self.planes!r} is not a list of axial positions in [0, 1]")

    @property
    def readings(self):
        """Readings per part: planes times directions."""
        return len(self.planes) * self.directions

    def reading_error(self, z):
        """Form error of the (mean) reading [m] from standard normals ``z`` (..., 3): ovality, angle, taper."""
        u = special.ndtr(np.asarray(z, dtype=float))
        ovality = self.ovality * u[..., 0]
        angle = np.pi * u[..., 1]
        taper = self.taper * (2.0 * u[..., 2] - 1.0)
        steps = np.pi * np.arange(self.directions) / self.directions
        seen = np.mean(np.cos(2.0 * (angle[..., None] + steps)), axis=-1)
        return 0.5 * ovality * seen + taper * (float(np.mean(self.planes)) - 0.5)


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
    form : FormError or None
        Form error of round parts and where they are read (journals).
    bolt_scatter : float
        Housing bores: standard deviation of the change of the bore between
        its reading and assembly [m]. The bore is machined and read with the
        cap bolted; at assembly it is bolted again, and the scatter of the
        bolt preload (torque tightening: a tightening factor of 1.4-1.6,
        VDI 2230) changes the bore by that share of its response to the
        preload. 0: the bore at assembly is the bore read.
    source : str
        Where the limits and process come from.
    """

    name: str
    lo: float
    hi: float
    process: object
    gauge: Gauge = Gauge()
    shared: float = 0.0
    form: FormError | None = None
    bolt_scatter: float = 0.0
    source: str = ""

    def __post_init__(self):
        check.limits(self.name, self.lo, self.hi)
        check.fields(self, _DIMENSION_CHECKS, prefix=f"{self.name} ")

    def read(self, true_size, z_gauge, z_form=None):
        """Readings [m] of parts of true (mean) size ``true_size``: form error, then the gauge.

        ``z_form`` (..., 3) standard normals are needed when the dimension has a form error.
        """
        if self.form is not None:
            true_size = true_size + self.form.reading_error(z_form)
        return self.gauge.read(true_size, z_gauge)

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


#: The engine file's name of each process form (``distribution = ...``).
DISTRIBUTION_NAMES = {Normal: "normal", TruncatedNormal: "truncated-normal", Uniform: "uniform", Mixture: "mixture",
                      ToolWear: "tool-wear", SkewNormal: "skew-normal"}
_DISTRIBUTIONS = tuple(DISTRIBUTION_NAMES.values())


def _spec_table(field, spec):
    """A TOML table as a dict, or a ValueError naming the field (a number or text where a table belongs)."""
    if not isinstance(spec, dict):
        raise ValueError(f"{field}: {spec!r} is not a table (write {{ key = value, ... }})")
    return dict(spec)


def _scalar(field, value):
    """One finite number from a file: text, true/false, lists and tables are refused, never converted."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ValueError(f"{field}: {value!r} is not a number")
    return float(check.finite(field, value))


#: Largest gauge error or form error a file may give [m]: 0.1 mm (a value in um written as mm is 1000 times more).
_SMALL_LENGTH = 0.1e-3


def _small_length(field, value, scale):
    """A gauge or form error in file units -> m, refused above :data:`_SMALL_LENGTH` with a hint about units."""
    v = _scalar(field, value)
    if abs(v * scale) > _SMALL_LENGTH:
        raise ValueError(f"{field}: {v:g} is not a plausible gauge or form error (at most {_SMALL_LENGTH / scale:g} "
                         "in the file's units); is `units` right?")
    return v * scale


def _positive_scalar(field, value):
    """One number > 0 from a file (as :func:`_scalar`)."""
    v = _scalar(field, value)
    if v <= 0:
        raise ValueError(f"{field}: {v:g} is not valid; must be > 0")
    return v


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
        {distribution = "skew-normal", mean = ..., sigma = ..., skewness = 0.5}   # skewness [-]

    Any form takes ``mean_shift`` (added to the process mean).
    """
    spec = _spec_table(field, spec)
    kind = check.one_of(f"{field}.distribution", spec.pop("distribution", "normal"), _DISTRIBUTIONS)
    shift = _scalar(f"{field}.mean_shift", spec.pop("mean_shift", 0.0)) * scale

    def length(key, default=None, *, positive=False):
        if key not in spec:
            if default is None:
                raise ValueError(f"{field}: missing key '{key}' for distribution '{kind}'")
            return default
        value = (_positive_scalar if positive else _scalar)(f"{field}.{key}", spec.pop(key))
        if key == "sigma":
            units = {v: k for k, v in UNITS.items()}.get(scale, f"x {scale:g} m")
            check.PLAUSIBLE["process_sigma"].check(f"{field}.sigma", value, scale=scale, unit=units)
        return value * scale

    middle = 0.5 * (lo + hi)
    both = [k for k in ("mean", "sigma") if k in spec]
    if kind == "normal" and "cpk" in spec and both:
        raise ValueError(f"{field}: give either cpk (with cp, side) or mean and sigma, not both: they are two ways "
                         f"of saying the same process (given: cpk, {', '.join(both)})")
    if kind == "normal" and "cpk" in spec:
        cpk = _positive_scalar(f"{field}.cpk", spec.pop("cpk"))
        cp = spec.pop("cp", None)
        cp = None if cp is None else _positive_scalar(f"{field}.cp", cp)
        try:  # checked here, the file's boundary, also where a caller trusts its inputs
            _cp_not_below_cpk({"cp": cp, "cpk": cpk})
        except ValueError as err:
            raise ValueError(f"{field}.{err}") from None
        side = check.one_of(f"{field}.side", spec.pop("side", "upper"), SIDES)
        process = Normal.from_capability(lo, hi, cpk=cpk, cp=cp, side=side)
    elif kind == "normal":
        process = Normal(length("mean", middle), length("sigma", positive=True))
    elif kind == "truncated-normal":
        process = TruncatedNormal(length("mean", middle), length("sigma", positive=True), length("lo", lo),
                                  length("hi", hi))
        if process.hi <= process.lo:
            raise ValueError(f"{field}: truncation hi {process.hi:.6g} m is not above lo {process.lo:.6g} m")
    elif kind == "uniform":
        process = Uniform(length("lo", lo), length("hi", hi))
        if process.hi <= process.lo:
            raise ValueError(f"{field}: uniform hi {process.hi:.6g} m is not above lo {process.lo:.6g} m")
    elif kind == "mixture":
        process = _mixture_from_spec(spec.pop("components", None), lo=lo, hi=hi, scale=scale, field=field)
    elif kind == "skew-normal":
        mean, sigma = length("mean", 0.5 * (lo + hi)), length("sigma", positive=True)
        skewness = _scalar(f"{field}.skewness", spec.pop("skewness", 0.0))
        if not abs(skewness) < MAX_SKEWNESS:
            raise ValueError(f"{field}.skewness: {skewness:g} is not valid; a skew-normal's skewness lies in "
                             f"(-{MAX_SKEWNESS:.4f}, {MAX_SKEWNESS:.4f})")
        process = SkewNormal(mean, sigma, skewness)
    else:
        process = ToolWear(length("start"), length("end"), length("sigma", positive=True))
    if spec:
        raise ValueError(f"{field}: unknown key(s) {sorted(spec)} for distribution '{kind}'")
    return process.shifted(shift) if shift else process


def _mixture_from_spec(items, *, lo, hi, scale, field):
    """A :class:`Mixture` from the ``components`` list of a process table: each a process table with a ``weight``."""
    if items is not None and not (isinstance(items, list) and all(isinstance(c, dict) for c in items)):
        raise ValueError(f"{field}.components: {items!r} is not a list of tables")
    if not items:
        raise ValueError(f"{field}.components: a mixture needs at least one component")
    weights = tuple(_scalar(f"{field}.components[{i}].weight", c.get("weight", np.nan)) for i, c in enumerate(items))
    components = tuple(process_from_spec({k: v for k, v in c.items() if k != "weight"}, lo=lo, hi=hi, scale=scale,
                                         field=f"{field}.components[{i}]")
                       for i, c in enumerate(items))
    return Mixture(components, weights)


def _whole_number(field, value):
    """A whole number from a file (true/false and 2.0 refused)."""
    if isinstance(value, bool) or not isinstance(value, int):
        raise ValueError(f"{field}: {value!r} is not a whole number")
    return value


def _known_keys(field, spec, known):
    unknown = set(spec) - known
    if unknown:
        raise ValueError(f"{field}: unknown key(s) {sorted(unknown)}; valid: {sorted(known)}")


def form_from_spec(spec, *, scale, field):
    """Build a :class:`FormError` from a TOML table (lengths in file units times ``scale``), or None."""
    if spec is None:
        return None
    spec = _spec_table(field, spec)
    _known_keys(field, spec, {"ovality", "taper", "planes", "directions"})
    planes = spec.get("planes", [0.5])
    if not isinstance(planes, list):
        raise ValueError(f"{field}.planes: {planes!r} is not a list of axial positions")
    values = dict(ovality=_small_length(f"{field}.ovality", spec.get("ovality", 0.0), scale),
                  taper=_small_length(f"{field}.taper", spec.get("taper", 0.0), scale),
                  planes=tuple(_scalar(f"{field}.planes", x) for x in planes),
                  directions=_whole_number(f"{field}.directions", spec.get("directions", 1)))
    try:
        return FormError(**values)
    except ValueError as err:
        raise ValueError(f"{field}: {err}") from None


def gauge_from_spec(spec, *, scale, field):
    """Build a :class:`Gauge` from a TOML table (lengths in file units times ``scale``)."""
    spec = _spec_table(field, {} if spec is None else spec)
    _known_keys(field, spec, {"bias", "repeatability", "resolution", "temperature", "expansion_mismatch", "readings",
                              "combine"})
    for key in ("bias", "repeatability", "resolution"):
        if key in spec:
            spec[key] = _small_length(f"{field}.{key}", spec[key], scale)
    for key in ("temperature", "expansion_mismatch"):
        if key in spec:
            spec[key] = _scalar(f"{field}.{key}", spec[key])
    if "readings" in spec:
        _whole_number(f"{field}.readings", spec["readings"])
    if "combine" in spec and not isinstance(spec["combine"], str):
        raise ValueError(f"{field}.combine: {spec['combine']!r} is not text")
    try:
        return Gauge(**spec)
    except ValueError as err:
        raise ValueError(f"{field}: {err}") from None
