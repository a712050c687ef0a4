r"""Which inputs drive the operating clearance and the film: regression-based sensitivity.

For an output :math:`y` and inputs :math:`x_k` of the same bearings, the
standardised regression coefficients :math:`\mathrm{SRC}_k = b_k\,\sigma_{x_k}/\sigma_y`
of the least-squares fit :math:`y \approx b_0 + \sum_k b_k x_k` give each
input's first-order share of the variance, :math:`\mathrm{SRC}_k^2`, when
the inputs are independent and the model is near linear; the fit's
:math:`R^2` says how much of the variance the linear model explains (the rest
is interaction and nonlinearity, e.g. grading steps). Intervals come from a
bootstrap over bearings. This is the contributor chart tolerance-analysis
tools show.

References
----------
.. [1] Saltelli, A. et al., *Global Sensitivity Analysis: The Primer*, Wiley,
   2008, sec. 1.2.5 (standardised regression coefficients).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from ._random import as_generator
from .assembly import ASSEMBLED

#: Inputs of a bearing (name -> how to read it from a one-scheme dataset, as (engines, bearings) arrays).
INPUTS = {
    "housing bore": lambda d: np.broadcast_to(d.housing_bore.values, d.status.shape),
    "journal": lambda d: np.broadcast_to(d.journal_d.values, d.status.shape),
    "upper shell wall": lambda d: d.shell_upper_wall.values,
    "lower shell wall": lambda d: d.shell_lower_wall.values,
    "crush height": lambda d: 0.5 * (d.shell_upper_crush.values + d.shell_lower_crush.values),
    "bore gauge error": lambda d: np.broadcast_to(d.housing_bore_reading.values - d.housing_bore.values, d.status.shape),
    "journal gauge error": lambda d: np.broadcast_to(d.journal_d_reading.values - d.journal_d.values, d.status.shape),
    "misalignment": lambda d: np.broadcast_to(np.linalg.norm(d.bore_offset.values, axis=-1), d.status.shape),
}


#: Largest number of bearings a fit uses (a seeded random subsample beyond it); the bootstrap
#: intervals show what that costs in precision.
MAX_BEARINGS = 20_000


def contributions(ds, scheme, *, output="clearance_operating", within_bearing=True, bootstrap=200, rng=0):
    """Variance contributions of the inputs to ``output`` for one scheme.

    Returns a DataFrame indexed by input: ``share`` (SRC^2 normalised to the
    explained variance), its 95 % bootstrap interval, ``src`` (signed), and
    the fit's ``r2`` in ``attrs``. Bearings where the output is not computed
    (NaN, marked by the status variables) are left out of the fit. With
    ``within_bearing`` the means of each main-bearing position are removed
    first: the position (its load) is a design fact, not a tolerance, and
    would otherwise swamp the film's variance.

    In selective assembly the shells are chosen from the measured bore and
    journal, so the inputs are correlated and the shares are a regression
    decomposition, not independent first-order indices; gauge error acts
    through the choice of shells and shows there.
    """
    d = ds.sel(scheme=scheme)
    if "mech_engine" in d[output].dims:  # a result of the mechanical chain: its engines only
        d = d.isel(engine=d.mech_engine.values).drop_vars("mech_engine").rename({"mech_engine": "engine"})
    y = d[output].values
    ok = (d.status.values == ASSEMBLED) & np.isfinite(y)
    columns = [np.array(INPUTS[k](d), dtype=float) for k in INPUTS]
    if within_bearing:
        def centred(a):
            masked = np.where(ok, a, np.nan)
            return a - np.nanmean(masked, axis=0, keepdims=True)

        columns = [centred(a) for a in columns]
        y = centred(y)
    x = np.column_stack([a[ok] for a in columns])
    y = y[ok]
    gen = as_generator(rng)
    if y.size > MAX_BEARINGS:
        pick = gen.choice(y.size, MAX_BEARINGS, replace=False)
        x, y = x[pick], y[pick]
    keep = x.std(axis=0) > 0  # an input with no spread in this study cannot contribute
    names = [k for k, use in zip(INPUTS, keep) if use]
    x = x[:, keep]
    if y.size <= x.shape[1] + 2:
        raise ValueError(f"output {output!r}: {y.size} bearings are too few for {x.shape[1]} inputs")

    def fit(rows):
        xs, ys = x[rows], y[rows]
        zx = (xs - xs.mean(axis=0)) / xs.std(axis=0)
        zy = (ys - ys.mean()) / ys.std()
        coef, *_ = np.linalg.lstsq(zx, zy, rcond=None)
        r2 = 1 - np.sum((zy - zx @ coef) ** 2) / np.sum(zy**2)
        return coef, r2

    coef, r2 = fit(np.arange(y.size))
    boot = np.array([fit(gen.integers(0, y.size, y.size))[0] ** 2 for _ in range(bootstrap)])
    share = coef**2 / np.sum(coef**2)
    boot_share = boot / boot.sum(axis=1, keepdims=True)
    frame = pd.DataFrame({
        "share": share,
        "share_lo": np.quantile(boot_share, 0.025, axis=0),
        "share_hi": np.quantile(boot_share, 0.975, axis=0),
        "src": coef,
    }, index=pd.Index(names, name="input")).sort_values("share", ascending=False)
    frame.attrs.update({"r2": float(r2), "bearings": int(y.size), "output": output, "scheme": str(scheme),
                        "within_bearing": within_bearing})
    return frame
